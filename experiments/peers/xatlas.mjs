// xatlas (jpcy/xatlas, through the npm package xatlasjs, its WebAssembly
// build) on one triangle mesh, measured as docs/results.md measures
// `--cut seams`: one JSON line with the charts, the symmetric Dirichlet
// energy (area-weighted over the whole atlas, and the largest chart's) at
// the atlas's best uniform scale (xatlas gives every chart one texel
// density), the seam length over the square root of the area, the atlas
// coverage, inverted triangles and xatlas's own seconds.
// Usage: node experiments/peers/xatlas.mjs XATLASJS_DIR MESH.off|MESH.obj
import { readFileSync } from "node:fs";
import { createRequire } from "node:module";
import { join } from "node:path";

const [dir, meshPath] = process.argv.slice(2);
if (!dir || !meshPath) {
  console.error("usage: node experiments/peers/xatlas.mjs XATLASJS_DIR MESH.off|MESH.obj");
  process.exit(2);
}

// Positions and triangles of an OFF or OBJ file (polygons as fans).
function readMesh(path) {
  const text = readFileSync(path, "utf8");
  const V = [], F = [];
  const fan = (corners) => { for (let k = 1; k + 1 < corners.length; ++k) F.push([corners[0], corners[k], corners[k + 1]]); };
  if (path.toLowerCase().endsWith(".off")) {
    const words = text.split("\n").map((l) => l.split("#")[0]).join(" ").trim().split(/\s+/);
    if (words[0] !== "OFF") throw new Error(`${path}: not an OFF file`);
    const nv = +words[1], nf = +words[2];
    let i = 4;
    for (let v = 0; v < nv; ++v, i += 3) V.push([+words[i], +words[i + 1], +words[i + 2]]);
    for (let f = 0; f < nf; ++f) {
      const n = +words[i];
      fan(words.slice(i + 1, i + 1 + n).map(Number));
      i += 1 + n;
    }
  } else {
    for (const line of text.split("\n")) {
      const w = line.trim().split(/\s+/);
      if (w[0] === "v") V.push([+w[1], +w[2], +w[3]]);
      if (w[0] === "f") fan(w.slice(1).map((c) => { const k = parseInt(c, 10); return k < 0 ? V.length + k : k - 1; }));
    }
  }
  return { V, F };
}

const require = createRequire(import.meta.url);
const createXAtlasModule = require(join(dir, "node_modules/xatlasjs/dist/node/xatlas.js"));
const { Api } = await import(join(dir, "node_modules/xatlasjs/dist/node/api.mjs"));
const XAtlas = Api(createXAtlasModule);
const atlas = await new Promise((resolve) => {
  const api = new XAtlas(() => resolve(api), (path, prefix) => join(dir, "node_modules/xatlasjs/dist/node", path));
});

const { V, F } = readMesh(meshPath);
if (V.length > 65535) throw new Error(`${meshPath}: xatlasjs takes at most 65535 vertices (16-bit indices)`);
atlas.createAtlas();
atlas.addMesh(new Uint16Array(F.flat()), new Float32Array(V.flat()));
const start = process.hrtime.bigint();
const result = atlas.generateAtlas({}, {}, true);
const seconds = Number(process.hrtime.bigint() - start) / 1e9;
const mesh = result.meshes[0];
const index = mesh.index, uv = mesh.vertex.coords1, old = mesh.oldIndexes;
const nf = index.length / 3, nv = mesh.vertexCount;

// Charts: the components of the output mesh (xatlas splits vertices on seams).
const parent = Array.from({ length: nv }, (_, i) => i);
const find = (i) => (parent[i] === i ? i : (parent[i] = find(parent[i])));
for (let f = 0; f < nf; ++f) for (let k = 1; k < 3; ++k) parent[find(index[3 * f + k])] = find(index[3 * f]);

// Per face: rest area and the map's Jacobian J (rest triangle in its own
// plane). A chart may come mirrored (its signed UV area negative); that is
// a valid texture map, so each face's det J is taken with its chart's sign,
// and a face whose sign differs from its chart's is inverted.
const faces = [];
const chartSign = new Map();
for (let f = 0; f < nf; ++f) {
  const [a, b, c] = [0, 1, 2].map((k) => index[3 * f + k]);
  const [p, q, r] = [a, b, c].map((v) => V[old[v]]);
  const e1 = [0, 1, 2].map((i) => q[i] - p[i]), e2 = [0, 1, 2].map((i) => r[i] - p[i]);
  const l1 = Math.hypot(...e1);
  const x1 = e1.map((t) => t / l1);
  const d = e2[0] * x1[0] + e2[1] * x1[1] + e2[2] * x1[2];
  const h = Math.hypot(...e2.map((t, i) => t - d * x1[i]));
  const restArea = 0.5 * l1 * h;
  if (!(restArea > 0)) continue;
  // The rest triangle (0,0), (l1,0), (d,h); J = [f1 f2] [[l1, d], [0, h]]^-1.
  // xatlasjs gives (u / width, v / height); back to texels.
  const u = [a, b, c].map((v) => [uv[2 * v] * result.width, uv[2 * v + 1] * result.height]);
  const f1 = [u[1][0] - u[0][0], u[1][1] - u[0][1]], f2 = [u[2][0] - u[0][0], u[2][1] - u[0][1]];
  const J = [
    [f1[0] / l1, (f2[0] - (d * f1[0]) / l1) / h],
    [f1[1] / l1, (f2[1] - (d * f1[1]) / l1) / h],
  ];
  const det = J[0][0] * J[1][1] - J[0][1] * J[1][0];
  const frob = J[0][0] ** 2 + J[0][1] ** 2 + J[1][0] ** 2 + J[1][1] ** 2;
  const chart = find(a);
  chartSign.set(chart, (chartSign.get(chart) ?? 0) + det * restArea);
  faces.push({ chart, restArea, det, frob });
}
let sumA = 0, sumB = 0, area = 0, uvArea = 0, inverted = 0;
const chartSums = new Map();
for (const { chart, restArea, det, frob } of faces) {
  uvArea += Math.abs(det) * restArea;
  if (!(det * Math.sign(chartSign.get(chart)) > 0)) { ++inverted; continue; }
  // |J|^2 and |J^-1|^2 = |J|^2 / det^2.
  const s = chartSums.get(chart) ?? { A: 0, B: 0, area: 0 };
  s.A += restArea * frob; s.B += (restArea * frob) / (det * det); s.area += restArea;
  chartSums.set(chart, s);
  sumA += restArea * frob; sumB += (restArea * frob) / (det * det); area += restArea;
}
// E(t) = (t^2 A + B / t^2) / area is least at t^4 = B / A.
const t2 = Math.sqrt(sumB / sumA);
const energy = (s) => (t2 * s.A + s.B / t2) / s.area;
let largest = 0;
for (const s of chartSums.values()) largest = Math.max(largest, energy(s));

// Seams: the output's boundary edges not on the input's boundary, each
// counted once (it borders two charts or a chart twice).
const key = (i, j) => (i < j ? `${i},${j}` : `${j},${i}`);
const count = (faces, vertexOf) => {
  const m = new Map();
  for (const f of faces) for (let k = 0; k < 3; ++k) {
    const e = key(vertexOf(f[k]), vertexOf(f[(k + 1) % 3]));
    m.set(e, (m.get(e) ?? 0) + 1);
  }
  return m;
};
const outFaces = Array.from({ length: nf }, (_, f) => [index[3 * f], index[3 * f + 1], index[3 * f + 2]]);
const outEdges = count(outFaces, (v) => v);
const inEdges = count(F, (v) => v);
let seam = 0;
for (const [e, n] of outEdges) {
  if (n !== 1) continue;
  const [i, j] = e.split(",").map(Number);
  if (inEdges.get(key(old[i], old[j])) === 1) continue;  // the input's own boundary
  const p = V[old[i]], q = V[old[j]];
  seam += Math.hypot(p[0] - q[0], p[1] - q[1], p[2] - q[2]) / 2;
}
console.log(JSON.stringify({
  mesh: meshPath.split("/").pop(), faces: F.length, charts: chartSums.size,
  energy: (t2 * sumA + sumB / t2) / area, largest_chart_energy: largest,
  seam_length: seam / Math.sqrt(area), coverage: uvArea / (result.width * result.height),
  inverted, seconds,
}));
atlas.destroyAtlas();
