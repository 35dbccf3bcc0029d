#!/usr/bin/env python3
"""Write a minimal page that follows the `amp view` page contract.

It stands in for real `amp view` output while developing the browser check
(viewer_browser_check.py), and its negative modes prove the check fails when
it should:

    viewer_fixture_page.py OUT.html             # good page: robot moves
    viewer_fixture_page.py OUT.html --broken    # throws after being ready
    viewer_fixture_page.py OUT.html --static    # robot never moves

The contract: #amp-frame range slider (min 0, max N-1) moves the robot on
'input'; #amp-play toggles playback; window.ampViewer = {frameCount, frame,
setFrame}; document.body.dataset.ampReady = "1" after the first render;
robot orange (#ff7f0e), world grey, start/goal ghosts green/purple and
translucent, path trace blue; rendering on demand.
"""
import argparse
import sys
from pathlib import Path

THREE_DIR = Path("/usr/share/javascript/three")
THREE_JS = THREE_DIR / "three.min.js"
ORBIT_JS = THREE_DIR / "examples/js/controls/OrbitControls.js"
FRAMES = 50

PAGE = """<!DOCTYPE html>
<html lang="en"><head><meta charset="utf-8">
<title>amp view fixture (%(mode)s)</title>
<style>
 html, body { margin: 0; height: 100%%; overflow: hidden; background: #fff; }
 #amp-canvas { position: absolute; inset: 0; }
 #amp-bar { position: absolute; left: 8px; right: 8px; bottom: 8px;
            display: flex; gap: 8px; font: 13px sans-serif; }
 #amp-frame { flex: 1; }
</style>
<script>%(three)s</script>
<script>%(orbit)s</script>
</head><body>
<div id="amp-canvas"></div>
<div id="amp-bar"><button id="amp-play">Play</button>
<input type="range" id="amp-frame" min="0" max="%(last)d" value="0" step="1">
<span id="amp-label">0</span>
<!-- An orange legend swatch over the canvas, as real pages have: the check
     must not count it as robot. -->
<span><span style="display:inline-block;width:14px;height:14px;background:#ff7f0e"></span>
robot</span></div>
<script>
%(app)s
</script>
</body></html>
"""

# The viewer itself. Placeholders: FRAMES, MOVES (false for --static),
# BROKEN (true for --broken).
APP = r"""
(function () {
  "use strict";
  const N = %(frames)d, MOVES = %(moves)s, BROKEN = %(broken)s;
  const host = document.getElementById("amp-canvas");
  const slider = document.getElementById("amp-frame");
  const label = document.getElementById("amp-label");
  const playBtn = document.getElementById("amp-play");

  const renderer = new THREE.WebGLRenderer({ antialias: true });
  renderer.setPixelRatio(window.devicePixelRatio);
  renderer.setSize(window.innerWidth, window.innerHeight);
  renderer.setClearColor(0xffffff);
  host.appendChild(renderer.domElement);

  const scene = new THREE.Scene();
  const camera = new THREE.PerspectiveCamera(
      45, window.innerWidth / window.innerHeight, 0.1, 100);
  camera.position.set(0, 9, 11);
  scene.add(new THREE.AmbientLight(0xffffff, 0.45));
  const sun = new THREE.DirectionalLight(0xffffff, 0.75);
  sun.position.set(4, 10, 6);
  scene.add(sun);

  // World: a floor slab and one obstacle, in greys.
  const grey = (c) => new THREE.MeshLambertMaterial({ color: c });
  const floor = new THREE.Mesh(new THREE.BoxGeometry(10, 0.2, 7), grey(0xb0b0b0));
  floor.position.y = -0.1;
  scene.add(floor);
  const wall = new THREE.Mesh(new THREE.BoxGeometry(1, 1.5, 1), grey(0x707070));
  wall.position.set(0, 0.75, -2.2);
  scene.add(wall);

  // Path: a straight line from start to goal, sampled at N frames.
  const start = new THREE.Vector3(-3.5, 0.5, 1.5);
  const goal = new THREE.Vector3(3.5, 0.5, -0.5);
  const path = [];
  for (let i = 0; i < N; ++i)
    path.push(start.clone().lerp(goal, i / (N - 1)));

  const robotGeom = new THREE.BoxGeometry(1, 1, 1);
  const ghost = (c) => new THREE.MeshLambertMaterial(
      { color: c, transparent: true, opacity: 0.3, depthWrite: false });
  const startGhost = new THREE.Mesh(robotGeom, ghost(0x2ca02c));
  startGhost.position.copy(start);
  const goalGhost = new THREE.Mesh(robotGeom, ghost(0x9467bd));
  goalGhost.position.copy(goal);
  scene.add(startGhost, goalGhost);
  const trace = new THREE.Line(
      new THREE.BufferGeometry().setFromPoints(path),
      new THREE.LineBasicMaterial({ color: 0x1f77b4 }));
  scene.add(trace);
  const robot = new THREE.Mesh(robotGeom, grey(0xff7f0e));
  scene.add(robot);

  const controls = new THREE.OrbitControls(camera, renderer.domElement);
  controls.target.set(0, 0, 0);
  controls.update();

  // Render on demand: one render per animation frame at most.
  let pending = false;
  function requestRender() {
    if (pending) return;
    pending = true;
    requestAnimationFrame(() => { pending = false; renderer.render(scene, camera); });
  }
  controls.addEventListener("change", requestRender);

  function setFrame(i) {
    i = Math.max(0, Math.min(N - 1, Math.round(Number(i))));
    viewer.frame = i;
    robot.position.copy(path[MOVES ? i : 0]);
    slider.value = String(i);
    label.textContent = String(i);
    requestRender();
  }
  const viewer = { frameCount: N, frame: 0, setFrame: setFrame };
  window.ampViewer = viewer;
  slider.addEventListener("input", () => setFrame(slider.value));

  let timer = null;
  playBtn.addEventListener("click", () => {
    if (timer) { clearInterval(timer); timer = null; playBtn.textContent = "Play"; return; }
    playBtn.textContent = "Pause";
    timer = setInterval(() => setFrame((viewer.frame + 1) %% N), 50);
  });
  window.addEventListener("resize", () => {
    camera.aspect = window.innerWidth / window.innerHeight;
    camera.updateProjectionMatrix();
    renderer.setSize(window.innerWidth, window.innerHeight);
    requestRender();
  });

  setFrame(0);
  requestAnimationFrame(() => {
    document.body.dataset.ampReady = "1";
    // --broken: the page is otherwise fine, so only the error check catches it.
    if (BROKEN) throw new Error("fixture: deliberately broken page");
  });
})();
"""


def build_page(mode):
    app = APP % {"frames": FRAMES,
                 "moves": "false" if mode == "static" else "true",
                 "broken": "true" if mode == "broken" else "false"}
    return PAGE % {"mode": mode, "last": FRAMES - 1, "app": app,
                   "three": THREE_JS.read_text(encoding="utf-8"),
                   "orbit": ORBIT_JS.read_text(encoding="utf-8")}


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("out", help="HTML file to write")
    group = ap.add_mutually_exclusive_group()
    group.add_argument("--broken", action="store_true",
                       help="the page throws an uncaught error once ready")
    group.add_argument("--static", action="store_true",
                       help="the robot does not move with the slider")
    args = ap.parse_args()
    mode = "broken" if args.broken else "static" if args.static else "good"
    try:
        html = build_page(mode)
    except OSError as exc:
        sys.exit(f"viewer_fixture_page: cannot read three.js ({exc}); "
                 "install libjs-three")
    Path(args.out).write_text(html, encoding="utf-8")
    print(f"wrote {args.out} ({mode}, {FRAMES} frames, {len(html)} bytes)")


if __name__ == "__main__":
    main()
