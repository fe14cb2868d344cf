// The page of `akvf view` (pictures/html_view.cpp embeds it with
// three.js and the data). The surface under a checkerboard of 16 x 16
// squares per unit of texture, orbit and zoom; the UV layout; a switch to
// colour both by the symmetric Dirichlet distortion (white = isometric,
// dark red = 10 or more above it, as in the SVG and PNG layouts). When done,
// #status holds a JSON self-check that the browser test reads: whether the
// surface was drawn, the fractions of dark and light pixels, and the errors.
(function () {
  'use strict';
  const statusElement = document.getElementById('status');
  const errors = [];
  function report(extra) {
    statusElement.textContent = JSON.stringify(Object.assign({ errors: errors }, extra || {}));
  }
  window.addEventListener('error', function (event) {
    errors.push(String(event.message));
    report({ drawn: false });
  });

  function decode(text, Type) {
    const binary = atob(text);
    const bytes = new Uint8Array(binary.length);
    for (let i = 0; i < binary.length; ++i) bytes[i] = binary.charCodeAt(i);
    return new Type(bytes.buffer);
  }

  const data = JSON.parse(document.getElementById('akvf-data').textContent);
  const P = decode(data.positions, Float32Array);
  const T = decode(data.uv, Float32Array);
  const I = decode(data.indices, Uint32Array);
  const C = decode(data.face_colors, Uint8Array);
  const S = decode(data.seams, Float32Array);
  document.getElementById('note').textContent =
    data.faces + ' faces, ' + data.vertices + ' vertices; mean distortion ' + data.mean_distortion.toFixed(4) +
    ' (symmetric Dirichlet, the map scaled to the surface\'s area; 4 = isometric)' + (data.degenerate_or_inverted ? '; ' + data.degenerate_or_inverted + ' faces inverted or collapsed' : '') +
    (S.length ? '; seams in red (' + S.length / 6 + ' edges)' : '') + (data.note ? '. ' + data.note : '');

  // Unindexed corners: a face's colour on each of its corners.
  const corners = I.length;
  const position = new Float32Array(3 * corners), uv = new Float32Array(2 * corners);
  const color = new Float32Array(3 * corners);
  for (let c = 0; c < corners; ++c) {
    const v = I[c], f = Math.floor(c / 3);
    position[3 * c] = P[3 * v]; position[3 * c + 1] = P[3 * v + 1]; position[3 * c + 2] = P[3 * v + 2];
    uv[2 * c] = T[2 * v]; uv[2 * c + 1] = T[2 * v + 1];  // in the unit square (html_view.cpp)
    color[3 * c] = C[3 * f] / 255; color[3 * c + 1] = C[3 * f + 1] / 255; color[3 * c + 2] = C[3 * f + 2] / 255;
  }

  function checkerCanvas(size, squares) {
    const canvas = document.createElement('canvas');
    canvas.width = canvas.height = size;
    const g = canvas.getContext('2d');
    const step = size / squares;
    for (let y = 0; y < squares; ++y)
      for (let x = 0; x < squares; ++x) {
        g.fillStyle = (x + y) % 2 ? 'rgb(40,40,40)' : 'rgb(235,235,235)';
        g.fillRect(x * step, y * step, step, step);
      }
    return canvas;
  }
  const checker = checkerCanvas(1024, 16);

  // The surface.
  const container = document.getElementById('surface');
  const renderer = new THREE.WebGLRenderer({ antialias: true, preserveDrawingBuffer: true });
  renderer.setPixelRatio(window.devicePixelRatio || 1);
  renderer.setClearColor(0xffffff);
  container.appendChild(renderer.domElement);
  const geometry = new THREE.BufferGeometry();
  geometry.setAttribute('position', new THREE.BufferAttribute(position, 3));
  geometry.setAttribute('uv', new THREE.BufferAttribute(uv, 2));
  geometry.setAttribute('color', new THREE.BufferAttribute(color, 3));
  geometry.computeVertexNormals();
  geometry.computeBoundingSphere();
  const texture = new THREE.CanvasTexture(checker);
  texture.anisotropy = renderer.capabilities.getMaxAnisotropy();
  // The surface sits a little behind its seams (polygon offset), so the lines show.
  const behind = { side: THREE.DoubleSide, polygonOffset: true, polygonOffsetFactor: 1, polygonOffsetUnits: 1 };
  const checkerMaterial = new THREE.MeshLambertMaterial(Object.assign({ map: texture }, behind));
  const distortionMaterial = new THREE.MeshLambertMaterial(Object.assign({ vertexColors: THREE.VertexColors }, behind));
  const surface = new THREE.Mesh(geometry, checkerMaterial);
  const scene = new THREE.Scene();
  scene.add(surface);
  if (S.length) {
    const seamGeometry = new THREE.BufferGeometry();
    seamGeometry.setAttribute('position', new THREE.BufferAttribute(S, 3));
    scene.add(new THREE.LineSegments(seamGeometry, new THREE.LineBasicMaterial({ color: 0xd01c1c })));
  }
  scene.add(new THREE.AmbientLight(0xffffff, 0.7));
  const camera = new THREE.PerspectiveCamera(35, 1, 1e-3, 1e3);
  const headlight = new THREE.DirectionalLight(0xffffff, 0.35);
  camera.add(headlight);
  scene.add(camera);
  const sphere = geometry.boundingSphere;
  camera.near = sphere.radius / 100;
  camera.far = sphere.radius * 100;
  // Seen from the front (+z, the file's usual up +y), a little from above and the side.
  camera.position.copy(sphere.center).add(new THREE.Vector3(0.35, 0.3, 1).normalize().multiplyScalar(sphere.radius * 2.7));
  const controls = new THREE.OrbitControls(camera, renderer.domElement);
  controls.target.copy(sphere.center);
  controls.addEventListener('change', render);

  // The layout.
  const layout = document.getElementById('layout');
  const pattern = layout.getContext('2d').createPattern(checker, 'repeat');

  function drawLayout(byDistortion) {
    const width = layout.clientWidth, height = layout.clientHeight, ratio = window.devicePixelRatio || 1;
    layout.width = width * ratio;
    layout.height = height * ratio;
    const g = layout.getContext('2d');
    g.setTransform(ratio, 0, 0, ratio, 0, 0);
    g.clearRect(0, 0, width, height);
    const side = Math.min(width, height) - 16;
    const x0 = (width - side) / 2, y0 = (height + side) / 2;
    // Texture (s, t) to pixels, t upwards.
    g.save();
    g.translate(x0, y0);
    g.scale(side, -side);
    if (!byDistortion) {
      pattern.setTransform(new DOMMatrix().scale(1 / checker.width, -1 / checker.height));
      g.fillStyle = pattern;
    }
    g.lineWidth = 0.5 / side;
    g.strokeStyle = 'rgba(0,0,0,0.25)';
    for (let c = 0; c < corners; c += 3) {
      g.beginPath();
      g.moveTo(uv[2 * c], uv[2 * c + 1]);
      g.lineTo(uv[2 * c + 2], uv[2 * c + 3]);
      g.lineTo(uv[2 * c + 4], uv[2 * c + 5]);
      g.closePath();
      if (byDistortion)
        g.fillStyle = 'rgb(' + C[c] + ',' + C[c + 1] + ',' + C[c + 2] + ')';
      g.fill();
      if (corners < 60000) g.stroke();
    }
    g.restore();
  }

  function render() {
    renderer.render(scene, camera);
  }

  function resize() {
    const width = container.clientWidth, height = container.clientHeight;
    renderer.setSize(width, height);
    camera.aspect = width / height;
    camera.updateProjectionMatrix();
    render();
    drawLayout(document.getElementById('distortion').checked);
  }
  window.addEventListener('resize', resize);
  const distortionSwitch = document.getElementById('distortion');
  function showDistortion(on) {
    surface.material = on ? distortionMaterial : checkerMaterial;
    render();
    drawLayout(on);
  }
  distortionSwitch.addEventListener('change', function () { showDistortion(distortionSwitch.checked); });
  // view.html#distortion opens with the switch on.
  distortionSwitch.checked = window.location.hash === '#distortion';
  surface.material = distortionSwitch.checked ? distortionMaterial : checkerMaterial;

  // The run's summary, if any: its scalar fields, nested ones by path.
  function rows(object, prefix, out) {
    for (const key of Object.keys(object)) {
      const value = object[key];
      if (value !== null && typeof value === 'object' && !Array.isArray(value)) rows(value, prefix + key + '.', out);
      else out.push([prefix + key, Array.isArray(value) ? JSON.stringify(value) : String(value)]);
    }
    return out;
  }
  if (data.summary) {
    const table = document.createElement('table');
    for (const [key, value] of rows(data.summary, '', [])) {
      const row = table.insertRow();
      row.insertCell().textContent = key;
      row.insertCell().textContent = value;
    }
    document.getElementById('summary').appendChild(table);
  }

  resize();

  // Self-check for the browser test: was the surface drawn with both colours?
  const gl = renderer.getContext();
  const w = gl.drawingBufferWidth, h = gl.drawingBufferHeight;
  const pixels = new Uint8Array(4 * w * h);
  gl.readPixels(0, 0, w, h, gl.RGBA, gl.UNSIGNED_BYTE, pixels);
  let dark = 0, light = 0, coloured = 0, background = 0;
  for (let i = 0; i < pixels.length; i += 4) {
    const luminance = (pixels[i] + pixels[i + 1] + pixels[i + 2]) / 3;
    if (pixels[i] === 255 && pixels[i + 1] === 255 && pixels[i + 2] === 255) ++background;
    else if (luminance < 90) ++dark;
    else if (luminance > 150) ++light;
    if (pixels[i] - pixels[i + 2] > 40) ++coloured;
  }
  const total = w * h;
  report({
    drawn: background < total, mode: distortionSwitch.checked ? 'distortion' : 'checker', width: w, height: h,
    dark: dark / total, light: light / total, coloured: coloured / total
  });
})();
