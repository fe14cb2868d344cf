"""Opens akvf's HTML views, and a binary glTF it wrote, in headless Chromium.

Run by ctest with Debian's /usr/bin/python3 (standard library only):
    /usr/bin/python3 tests/browser/check_pages.py AKVF THREE_DIR
For each page: the page's own self-check (#status, written after the first
frame: drawn, no error, the fractions of dark and light pixels in the WebGL
canvas), no console message at all in Chromium's log, and a screenshot whose
3D area is not blank and shows the checkerboard's two colours. Prints
"SKIPPED: ..." (ctest marks the test skipped) when chromium is not installed.
"""
import base64
import json
import math
import os
import shutil
import struct
import subprocess
import sys
import tempfile
import zlib

CHROMIUM_FLAGS = ["--headless", "--no-sandbox", "--use-angle=swiftshader", "--enable-unsafe-swiftshader",
                  "--window-size=1280,900", "--virtual-time-budget=15000", "--hide-scrollbars",
                  "--enable-logging=stderr", "--v=0"]


def fail(message):
    print("FAIL: " + message)
    sys.exit(1)


def run(command, **kwargs):
    result = subprocess.run(command, capture_output=True, text=True, timeout=300, **kwargs)
    if result.returncode != 0:
        fail("%s exited %d\n%s%s" % (" ".join(command), result.returncode, result.stdout, result.stderr))
    return result


def chromium(chrome, work, url, *extra):
    profile = tempfile.mkdtemp(dir=work, prefix="profile-")
    return run([chrome] + CHROMIUM_FLAGS + ["--user-data-dir=" + profile] + list(extra) + [url])


def png_pixels(path):
    """(width, height, rows of (r, g, b)) of an 8-bit RGB or RGBA PNG."""
    data = open(path, "rb").read()
    if data[:8] != b"\x89PNG\r\n\x1a\n":
        fail(path + " is not a PNG")
    at, idat, header = 8, b"", None
    while at < len(data):
        length, kind = struct.unpack(">I4s", data[at:at + 8])
        body = data[at + 8:at + 8 + length]
        if kind == b"IHDR":
            header = struct.unpack(">IIBBBBB", body)
        elif kind == b"IDAT":
            idat += body
        at += 12 + length
    width, height, depth, color, _, _, interlace = header
    if depth != 8 or color not in (2, 6) or interlace:
        fail("%s: unexpected PNG format (depth %d, colour type %d)" % (path, depth, color))
    channels = 3 if color == 2 else 4
    raw = zlib.decompress(idat)
    stride = width * channels
    rows, previous = [], bytearray(stride)
    for y in range(height):
        kind, line = raw[y * (stride + 1)], bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
        for i in range(stride):
            left = line[i - channels] if i >= channels else 0
            up, upper_left = previous[i], previous[i - channels] if i >= channels else 0
            if kind == 1:
                line[i] = (line[i] + left) & 255
            elif kind == 2:
                line[i] = (line[i] + up) & 255
            elif kind == 3:
                line[i] = (line[i] + (left + up) // 2) & 255
            elif kind == 4:
                p = left + up - upper_left
                pa, pb, pc = abs(p - left), abs(p - up), abs(p - upper_left)
                line[i] = (line[i] + (left if pa <= pb and pa <= pc else up if pb <= pc else upper_left)) & 255
        rows.append([tuple(line[x * channels:x * channels + 3]) for x in range(width)])
        previous = line
    return width, height, rows


def open_page(chrome, work, url):
    """The page's DOM after it ran; fails on any console message."""
    dom = chromium(chrome, work, url, "--dump-dom")
    console = [line for line in dom.stderr.splitlines() if "CONSOLE" in line]
    if console:
        fail("%s logged to the console:\n%s" % (url, "\n".join(console)))
    return dom


def check_page(chrome, work, page, expect_coloured=False, crop=(0.0, 0.06, 0.58, 0.64)):
    url = "file://" + page
    dom = open_page(chrome, work, url)
    marker = '<pre id="status">'
    start = dom.stdout.find(marker)
    if start < 0:
        fail(url + ": no #status element in the page")
    text = dom.stdout[start + len(marker):dom.stdout.find("</pre>", start)]
    try:
        status = json.loads(text.replace("&quot;", '"').replace("&amp;", "&"))
    except ValueError:
        fail("%s: the page did not finish its self-check (status: %r)" % (url, text))
    print("%s: %s" % (url, json.dumps(status)))
    if status.get("errors"):
        fail(url + ": the page reported errors: %s" % status["errors"])
    if not status.get("drawn"):
        fail(url + ": the WebGL canvas is blank")
    if expect_coloured:
        if status.get("mode") != "distortion" or status.get("coloured", 0) < 0.005:
            fail(url + ": the distortion colours are missing")
    elif status.get("dark", 0) < 0.005 or status.get("light", 0) < 0.005:
        fail(url + ": the checkerboard's two colours are not both in the canvas")

    if expect_coloured:
        return
    shot = os.path.join(work, "shot.png")
    if os.path.exists(shot):
        os.remove(shot)
    chromium(chrome, work, url, "--screenshot=" + shot)
    width, height, rows = png_pixels(shot)
    x0, y0, x1, y1 = (int(crop[0] * width), int(crop[1] * height), int(crop[2] * width), int(crop[3] * height))
    dark = light = drawn = total = 0
    for y in range(y0, y1, 2):
        for x in range(x0, x1, 2):
            r, g, b = rows[y][x]
            total += 1
            drawn += (r, g, b) != (255, 255, 255)
            luminance = (r + g + b) / 3
            dark += luminance < 90
            light += 150 < luminance < 250
    print("  screenshot %dx%d, 3D area: %.3f drawn, %.3f dark, %.3f light" %
          (width, height, drawn / total, dark / total, light / total))
    if drawn / total < 0.01:
        fail(url + ": the screenshot's 3D area is blank")
    if dark / total < 0.005 or light / total < 0.005:
        fail(url + ": the screenshot's 3D area lacks the checkerboard's two colours")


def torus_off(path, n=24, m=12):
    with open(path, "w") as out:
        out.write("OFF\n%d %d 0\n" % (n * m, 2 * n * m))
        for j in range(m):
            for i in range(n):
                u, v = 2 * math.pi * i / n, 2 * math.pi * j / m
                out.write("%.17g %.17g %.17g\n" % ((2 + math.cos(v)) * math.cos(u), (2 + math.cos(v)) * math.sin(u),
                                                  math.sin(v)))
        for j in range(m):
            for i in range(n):
                a, b = j * n + i, j * n + (i + 1) % n
                c, d = ((j + 1) % m) * n + i, ((j + 1) % m) * n + (i + 1) % n
                out.write("3 %d %d %d\n3 %d %d %d\n" % (a, b, d, a, d, c))


def glb_page(path, glb, three_dir):
    """A page that loads the GLB with three.js's own glTF loader and checks it as the views check themselves."""
    data = base64.b64encode(open(glb, "rb").read()).decode()
    with open(path, "w") as out:
        out.write("""<!doctype html><html><body style="margin:0"><pre id="status">loading</pre>
<script src="file://%s/three.min.js"></script>
<script src="file://%s/examples/js/loaders/GLTFLoader.js"></script>
<script>
const errors = [];
function report(extra) { document.getElementById('status').textContent = JSON.stringify(Object.assign({errors: errors}, extra)); }
window.addEventListener('error', e => { errors.push(String(e.message)); report({drawn: false}); });
const binary = atob('%s');
const bytes = new Uint8Array(binary.length);
for (let i = 0; i < binary.length; ++i) bytes[i] = binary.charCodeAt(i);
const renderer = new THREE.WebGLRenderer({preserveDrawingBuffer: true});
renderer.setSize(640, 480);
renderer.setClearColor(0xffffff);
document.body.appendChild(renderer.domElement);
new THREE.GLTFLoader().parse(bytes.buffer, '', function (gltf) {
  const scene = new THREE.Scene();
  scene.add(gltf.scene, new THREE.AmbientLight(0xffffff, 1.0));
  const box = new THREE.Box3().setFromObject(gltf.scene), center = box.getCenter(new THREE.Vector3());
  const radius = box.getSize(new THREE.Vector3()).length() / 2;
  const camera = new THREE.PerspectiveCamera(35, 640 / 480, radius / 100, radius * 100);
  camera.position.set(center.x, center.y, center.z + 3.2 * radius);
  let map = null;
  gltf.scene.traverse(o => { if (o.material && o.material.map) map = o.material.map; });
  let tries = 0;
  (function draw() {
    if (!map || !map.image || !map.image.complete) { if (++tries < 100) return setTimeout(draw, 100); }
    renderer.render(scene, camera);
    const gl = renderer.getContext(), pixels = new Uint8Array(4 * 640 * 480);
    gl.readPixels(0, 0, 640, 480, gl.RGBA, gl.UNSIGNED_BYTE, pixels);
    let dark = 0, light = 0, background = 0;
    for (let i = 0; i < pixels.length; i += 4) {
      const l = (pixels[i] + pixels[i + 1] + pixels[i + 2]) / 3;
      if (pixels[i] === 255 && pixels[i + 1] === 255 && pixels[i + 2] === 255) ++background;
      else if (l < 90) ++dark; else if (l > 150) ++light;
    }
    const n = 640 * 480;
    report({drawn: background < n, textured: !!map, dark: dark / n, light: light / n});
  })();
}, function (error) { errors.push(String(error)); report({drawn: false}); });
</script></body></html>
""" % (three_dir, three_dir, data))


def main():
    akvf, three_dir = sys.argv[1], sys.argv[2]
    chrome = shutil.which("chromium")
    if not chrome:
        print("SKIPPED: chromium is not installed (bash scripts/setup.sh installs it)")
        return
    if not os.path.exists(os.path.join(three_dir, "three.min.js")):
        print("SKIPPED: three.js not found in %s (bash scripts/setup.sh installs libjs-three)" % three_dir)
        return
    work = tempfile.mkdtemp(prefix="akvf_browser_")
    try:
        torus = os.path.join(work, "torus.off")
        torus_off(torus)
        base = os.path.join(work, "torus")
        run([akvf, "param", torus, "--cut", "auto", "--out", base + ".obj", "--summary", base + ".json",
             "--view", base + ".html", "--quiet"])
        run([akvf, "param", torus, "--cut", "auto", "--out", base + ".glb", "--quiet"])
        run([akvf, "view", base + ".obj", "--summary", base + ".json", "--out", base + "_view.html"])
        demo = os.path.join(work, "demo")
        run([akvf, "demo", "--out-dir", demo, "--quiet"])
        check_page(chrome, work, base + ".html")
        check_page(chrome, work, base + "_view.html")
        check_page(chrome, work, base + ".html#distortion", expect_coloured=True)
        check_page(chrome, work, os.path.join(demo, "demo_view.html"))
        if os.environ.get("AKVF_PYTHON_PACKAGE"):  # akvf.write_view from Python, on the same torus
            script = ("import akvf; V, F = akvf.read_mesh(%r); r = akvf.parameterize(V, F, cut='auto'); "
                      "akvf.write_view(%r, V, F, r.uv, r.uv_faces, summary={'status': r.status})"
                      % (torus, base + "_python.html"))
            run([sys.executable, "-c", script], env=dict(os.environ, PYTHONPATH=os.environ["AKVF_PYTHON_PACKAGE"]))
            check_page(chrome, work, base + "_python.html")
        manifest = os.path.join(work, "m.json")
        with open(manifest, "w") as out:
            out.write('{"name": "browser", "meshes": [{"label": "torus", "file": "torus.off"}], '
                      '"methods": [{"label": "akvf", "cut": "auto", "max_iters": 30}]}')
        results = os.path.join(work, "results")
        run([akvf, "experiment", manifest, "--data-dir", work, "--out-dir", results, "--views"])
        index = open_page(chrome, work, "file://" + os.path.join(results, "index.html"))
        if 'href="cases/torus--akvf/view.html"' not in index.stdout:
            fail("the experiment's index.html does not link the case's view")
        check_page(chrome, work, os.path.join(results, "cases", "torus--akvf", "view.html"))
        page = os.path.join(work, "glb.html")
        glb_page(page, base + ".glb", three_dir)
        check_page(chrome, work, page, crop=(0.0, 0.0, 0.5, 0.53))
        print("all pages drawn, no console message")
    finally:
        shutil.rmtree(work, ignore_errors=True)


if __name__ == "__main__":
    main()
