// The AMP 3-D viewer (`amp view`, docs/viewer.md): builds a three.js scene from the page's own data
// (#amp-scene: JSON; #amp-data: one base64 buffer of float32 vertices and poses, uint32 triangles)
// and moves the robot along the path. Everything it needs is in the page: it opens from disk.
(function () {
  'use strict';

  const kColours = { world: 0xb4b4b4, robot: 0xff7f0e, start: 0x2ca02c, goal: 0x9467bd,
                     path: 0x1f77b4, roadmap: 0x8c8c8c };
  const kFramesPerSecond = 30;

  function fail(message) {
    const box = document.getElementById('amp-error');
    box.textContent = message;
    box.hidden = false;
    console.error(message);
  }

  function decodeBase64(text) {
    const bin = atob(text);
    const bytes = new Uint8Array(bin.length);
    for (let i = 0; i < bin.length; ++i) bytes[i] = bin.charCodeAt(i);
    return bytes.buffer;
  }

  // A mesh part of the buffer as a geometry with one normal per face: world meshes are triangle
  // soups (shared vertices across creases), so smooth normals would shade them wrongly.
  function geometryOf(buffer, part) {
    const g = new THREE.BufferGeometry();
    const vertices = new Float32Array(buffer, part.vertices[0], part.vertices[1] * 3);
    g.setAttribute('position', new THREE.BufferAttribute(vertices, 3));
    g.setIndex(new THREE.BufferAttribute(new Uint32Array(buffer, part.triangles[0], part.triangles[1] * 3), 1));
    const faceted = g.toNonIndexed();
    faceted.computeVertexNormals();
    return faceted;
  }

  function material(colour, opacity) {
    const m = new THREE.MeshLambertMaterial({ color: colour, side: THREE.DoubleSide });
    if (opacity < 1) {
      m.transparent = true;
      m.opacity = opacity;
      m.depthWrite = false;
      // Pushed back in depth: where a ghost and the robot coincide (at the start, at the goal), the
      // robot shows in its own colour instead of tinted by the ghost.
      m.polygonOffset = true;
      m.polygonOffsetFactor = 2;
      m.polygonOffsetUnits = 2;
    }
    return m;
  }

  // The robot where the world hides it, faint and unshaded: drawn only where something nearer is
  // already drawn (depth test "greater"), so that a robot inside a maze still shows through its
  // walls while its visible parts keep their shading.
  function hiddenMaterial(colour) {
    return new THREE.MeshBasicMaterial({ color: colour, transparent: true, opacity: 0.45, depthWrite: false,
                                         depthFunc: THREE.GreaterDepth });
  }

  // One robot: a group of link meshes sharing the link geometries.
  function makeRobot(geometries, colour, opacity, hidden) {
    const group = new THREE.Group();
    const mat = hidden ? hiddenMaterial(colour) : material(colour, opacity);
    const links = geometries.map(function (g) {
      const mesh = new THREE.Mesh(g || new THREE.BufferGeometry(), mat);
      group.add(mesh);
      return mesh;
    });
    return { group: group, links: links };
  }

  function placeRobot(robot, poses, offset) {
    for (let j = 0; j < robot.links.length; ++j) {
      const p = offset + 7 * j;
      robot.links[j].position.set(poses[p], poses[p + 1], poses[p + 2]);
      robot.links[j].quaternion.set(poses[p + 3], poses[p + 4], poses[p + 5], poses[p + 6]);
    }
  }

  function lines(buffer, part, colour, opacity, segments) {
    const g = new THREE.BufferGeometry();
    g.setAttribute('position', new THREE.BufferAttribute(new Float32Array(buffer, part[0], part[1] * 3), 3));
    const m = new THREE.LineBasicMaterial({ color: colour, transparent: opacity < 1, opacity: opacity });
    return segments ? new THREE.LineSegments(g, m) : new THREE.Line(g, m);
  }

  // Looks at the page's focus (the robot at start and goal and the path; a 2-D world: all of it)
  // from the page's view direction, far enough to see all of the focus.
  function placeCamera(camera, controls, meta) {
    const f = meta.focus;
    const centre = new THREE.Vector3((f[0] + f[3]) / 2, (f[1] + f[4]) / 2, (f[2] + f[5]) / 2);
    const size = Math.max(1e-9, Math.hypot(f[3] - f[0], f[4] - f[1], f[5] - f[2]));
    const b = meta.bounds;
    const world = Math.max(size, Math.hypot(b[3] - b[0], b[4] - b[1], b[5] - b[2]));
    const look = new THREE.Vector3(meta.view[0], meta.view[1], meta.view[2]).normalize();
    camera.near = size / 1000;
    camera.far = world * 20;
    // The focus's bounding sphere fits the narrower of the two fields of view, with a margin.
    const halfFov = camera.fov * Math.PI / 360;
    const narrow = Math.min(halfFov, Math.atan(Math.tan(halfFov) * camera.aspect));
    camera.position.copy(centre).addScaledVector(look, 1.1 * (size / 2) / Math.sin(narrow));
    camera.updateProjectionMatrix();
    controls.target.copy(centre);
    controls.update();
  }

  function build() {
    const meta = JSON.parse(document.getElementById('amp-scene').textContent);
    const buffer = decodeBase64(document.getElementById('amp-data').textContent.trim());
    const view = document.getElementById('amp-view');
    const renderer = new THREE.WebGLRenderer({ antialias: true, preserveDrawingBuffer: true });
    renderer.setPixelRatio(window.devicePixelRatio || 1);
    renderer.setClearColor(0xf7f7f4);
    view.appendChild(renderer.domElement);

    const scene = new THREE.Scene();
    const camera = new THREE.PerspectiveCamera(40, 1, 0.01, 100);
    camera.up.set(0, 0, 1);
    scene.add(new THREE.HemisphereLight(0xffffff, 0x606060, 0.75));
    const headlight = new THREE.DirectionalLight(0xffffff, 0.45);
    headlight.position.set(0.3, 0.6, 1);
    camera.add(headlight);
    scene.add(camera);

    const worldMaterial = material(kColours.world, 1);
    // The cutaway: world surfaces nearer the camera than the focus are not drawn, so that a robot
    // inside a closed world (Twistycool's box, a shelf) shows from any side.
    const cut = new THREE.Plane(new THREE.Vector3(0, 0, 1), 0);
    if (!meta.flat) worldMaterial.clippingPlanes = [cut];
    renderer.localClippingEnabled = true;
    meta.obstacles.forEach(function (part) { scene.add(new THREE.Mesh(geometryOf(buffer, part), worldMaterial)); });
    const linkGeometries = meta.links.map(function (part) {
      return part.triangles[1] > 0 ? geometryOf(buffer, part) : null;
    });
    const poses = new Float32Array(buffer, meta.poses.offset, meta.poses.frames * meta.links.length * 7);
    const ghosts = [['start', kColours.start], ['goal', kColours.goal]];
    ghosts.forEach(function (ghost) {
      const robot = makeRobot(linkGeometries, ghost[1], 0.35, false);
      placeRobot(robot, new Float32Array(buffer, meta[ghost[0]], meta.links.length * 7), 0);
      robot.group.renderOrder = 1;
      scene.add(robot.group);
    });
    if (meta.trace[1] > 1) scene.add(lines(buffer, meta.trace, kColours.path, 1, false));
    if (meta.roadmap && meta.roadmap[1] > 0) scene.add(lines(buffer, meta.roadmap, kColours.roadmap, 0.55, true));
    const robot = makeRobot(linkGeometries, kColours.robot, 1, false);
    scene.add(robot.group);
    const hiddenRobot = makeRobot(linkGeometries, kColours.robot, 1, true);
    hiddenRobot.group.renderOrder = 2;
    scene.add(hiddenRobot.group);

    const controls = new THREE.OrbitControls(camera, renderer.domElement);
    return { meta: meta, renderer: renderer, scene: scene, camera: camera, controls: controls,
             robots: [robot, hiddenRobot], poses: poses, view: view, cut: cut, worldMaterial: worldMaterial };
  }

  // Moves the cut to the focus box's near side as seen from the camera: a point p of the world is
  // drawn when (p - centre) . n <= the box's reach along n, n pointing from the centre to the camera.
  function placeCut(v) {
    const f = v.meta.focus;
    const centre = new THREE.Vector3((f[0] + f[3]) / 2, (f[1] + f[4]) / 2, (f[2] + f[5]) / 2);
    const n = v.camera.position.clone().sub(centre).normalize();
    const reach = (Math.abs(n.x) * (f[3] - f[0]) + Math.abs(n.y) * (f[4] - f[1]) + Math.abs(n.z) * (f[5] - f[2])) / 2;
    v.cut.normal.copy(n).negate();
    v.cut.constant = reach * 1.05 + n.dot(centre);
  }

  function start() {
    if (typeof THREE === 'undefined' || typeof THREE.OrbitControls === 'undefined') {
      fail('three.js did not load');
      return;
    }
    let v;
    try {
      v = build();
    } catch (e) {
      fail('the scene could not be built: ' + e.message);
      return;
    }
    const slider = document.getElementById('amp-frame');
    const label = document.getElementById('amp-frame-label');
    const play = document.getElementById('amp-play');
    const frames = v.meta.poses.frames;
    let pending = false;
    let playing = false;
    let lastTick = 0;

    function render() {
      if (pending) return;
      pending = true;
      requestAnimationFrame(function () {
        pending = false;
        placeCut(v);
        v.renderer.render(v.scene, v.camera);
      });
    }
    function setFrame(i) {
      const f = Math.max(0, Math.min(frames - 1, Math.round(i)));
      api.frame = f;
      slider.value = String(f);
      label.textContent = 'frame ' + (f + 1) + ' of ' + frames + ' · ' +
        (frames > 1 ? Math.round(100 * f / (frames - 1)) : 100) + '% of the path';
      v.robots.forEach(function (r) { placeRobot(r, v.poses, f * v.meta.links.length * 7); });
      render();
    }
    function tick(time) {
      if (!playing) return;
      if (time - lastTick >= 1000 / kFramesPerSecond) {
        lastTick = time;
        if (api.frame >= frames - 1) {
          playing = false;
          play.textContent = 'Play';
          return;
        }
        setFrame(api.frame + 1);
      }
      requestAnimationFrame(tick);
    }
    function resize() {
      const w = v.view.clientWidth, h = v.view.clientHeight;
      v.renderer.setSize(w, h);
      v.camera.aspect = w / Math.max(1, h);
      v.camera.updateProjectionMatrix();
      render();
    }

    const api = { frameCount: frames, frame: 0, setFrame: setFrame };
    window.ampViewer = api;
    slider.max = String(frames - 1);
    slider.disabled = frames < 2;
    play.disabled = frames < 2;
    slider.addEventListener('input', function () { setFrame(Number(slider.value)); });
    play.addEventListener('click', function () {
      playing = !playing;
      play.textContent = playing ? 'Pause' : 'Play';
      if (playing) {
        if (api.frame >= frames - 1) setFrame(0);
        requestAnimationFrame(tick);
      }
    });
    v.controls.addEventListener('change', render);
    const cutaway = document.getElementById('amp-cutaway');
    cutaway.disabled = v.meta.flat;
    cutaway.checked = !v.meta.flat;
    cutaway.addEventListener('change', function () {
      v.worldMaterial.clippingPlanes = cutaway.checked ? [v.cut] : [];
      v.worldMaterial.needsUpdate = true;
      render();
    });
    window.addEventListener('resize', resize);
    resize();
    placeCamera(v.camera, v.controls, v.meta);
    setFrame(0);
    requestAnimationFrame(function () {
      requestAnimationFrame(function () { document.body.dataset.ampReady = '1'; });
    });
  }

  window.addEventListener('error', function (e) { fail('error: ' + e.message); });
  start();
})();
