// report.html's 3D viewer: plays the run's replay.glb (embedded as base64) with three.js
// (the global THREE of the vendored bundle), shows the chosen car's telemetry at the
// scrubbed time, and exposes window.report for the browser check (sim/tests/replay).
//
// Frames: the glTF root maps the simulator's z-up frame to y-up, so inside a car's node
// x is forward, y left and z up (m), as in the simulator.
"use strict";
(() => {
  const data = JSON.parse(document.getElementById("report-data").textContent);
  const el = (id) => document.getElementById(id);
  const ui = {
    viewer: el("viewer"), part: el("part"), play: el("play"), time: el("time"),
    clock: el("clock"), speed: el("speed"), car: el("car"), camera: el("camera"),
    values: el("values"),
  };
  // The camera of the follow mode, in lengths of the car from its centre (car frame: behind,
  // to its left, above): a three-quarter view from behind in which the car fills about a
  // fifth of the frame whatever its size.
  const CHASE = { back: 1.25, left: 0.55, up: 0.6 };
  const UNITS = {
    time_s: "s", x_m: "m", y_m: "m", yaw_rad: "rad", speed_kmh: "km/h", rpm: "rpm", gear: "",
    steering_rad: "rad", throttle: "", brake: "", lateral_accel_mps2: "m/s²",
    longitudinal_accel_mps2: "m/s²",
  };

  const state = {
    time: 0, playing: true, speed: 1, car: 0, mode: "follow", part: null,
    clip: null, action: null, duration: 0,
  };

  const renderer = new THREE.WebGLRenderer({ antialias: true, preserveDrawingBuffer: true });
  renderer.setPixelRatio(window.devicePixelRatio);
  ui.viewer.appendChild(renderer.domElement);
  const scene = new THREE.Scene();
  scene.background = new THREE.Color(0xe8ecef);
  scene.add(new THREE.HemisphereLight(0xffffff, 0x5a5a5a, 2.0));
  const sun = new THREE.DirectionalLight(0xffffff, 1.5);
  sun.position.set(0.4, 1, 0.3);
  scene.add(sun);
  const camera = new THREE.PerspectiveCamera(45, 16 / 9, 0.05, 20000);
  const controls = new THREE.OrbitControls(camera, renderer.domElement);
  controls.enabled = false;

  let mixer = null;
  let clips = [];
  // Per car: its node, and its body's centre, length and vertices in the car's frame (m):
  // the camera aims at the visible body, not at the box around the wheels and lamps.
  let cars = [];

  function resize() {
    const w = ui.viewer.clientWidth;
    const h = ui.viewer.clientHeight;
    renderer.setSize(w, h);
    camera.aspect = w / h;
    camera.updateProjectionMatrix();
  }

  function decodeBase64(text) {
    const binary = atob(text.trim());
    const bytes = new Uint8Array(binary.length);
    for (let i = 0; i < binary.length; i++) bytes[i] = binary.charCodeAt(i);
    return bytes.buffer;
  }

  // The bounding box, in the frame of `frame`, of the visible meshes under `node` (m).
  function boxIn(frame, node) {
    frame.updateWorldMatrix(true, true);
    const toFrame = frame.matrixWorld.clone().invert();
    const box = new THREE.Box3();
    node.traverse((o) => {
      if (!o.isMesh) return;
      o.geometry.computeBoundingBox();
      const m = new THREE.Matrix4().multiplyMatrices(toFrame, o.matrixWorld);
      if (Math.abs(m.determinant()) < 1e-12) return; // a hidden lamp (scale 0)
      box.union(o.geometry.boundingBox.clone().applyMatrix4(m));
    });
    return box;
  }

  // The vertices of the visible meshes under `node` in the frame of `frame` (m), at most
  // about `most` of them (evenly picked).
  function pointsIn(frame, node, most) {
    frame.updateWorldMatrix(true, true);
    const toFrame = frame.matrixWorld.clone().invert();
    const points = [];
    node.traverse((o) => {
      if (!o.isMesh) return;
      const m = new THREE.Matrix4().multiplyMatrices(toFrame, o.matrixWorld);
      if (Math.abs(m.determinant()) < 1e-12) return;
      const at = o.geometry.getAttribute("position");
      const step = Math.max(1, Math.floor(at.count / most));
      for (let i = 0; i < at.count; i += step) {
        points.push(new THREE.Vector3().fromBufferAttribute(at, i).applyMatrix4(m));
      }
    });
    return points;
  }

  // Turns the follow camera to the middle of the body as seen: the centre of the rectangle
  // around its projected vertices. Seen from behind and above, perspective draws the near end
  // larger and lower than the far one, so the body's 3D centre projects above the middle of
  // its image; two turns bring the middle within a pixel.
  function aimAtBody(car, centre) {
    const p = new THREE.Vector3();
    for (let turn = 0; turn < 2; turn++) {
      camera.updateMatrixWorld();
      let [x0, y0, x1, y1] = [Infinity, Infinity, -Infinity, -Infinity];
      for (const v of car.points) {
        p.copy(v).applyMatrix4(car.node.matrixWorld).project(camera);
        [x0, y0, x1, y1] = [Math.min(x0, p.x), Math.min(y0, p.y), Math.max(x1, p.x), Math.max(y1, p.y)];
      }
      if (!(x0 <= x1 && y0 <= y1)) return centre;
      const depth = centre.clone().project(camera).z;
      const aim = new THREE.Vector3((x0 + x1) / 2, (y0 + y1) / 2, depth).unproject(camera);
      camera.lookAt(aim);
      centre = aim;
    }
    return centre;
  }

  // The loaded objects by glTF node index. Names are no key: the loader renames a node whose
  // name another has (a car named "world" or "ground"), so the page gives node indices.
  function nodesByIndex(gltf) {
    const found = new Map();
    gltf.scene.traverse((o) => {
      const a = gltf.parser.associations.get(o);
      if (a && a.nodes !== undefined && !found.has(a.nodes)) found.set(a.nodes, o);
    });
    return found;
  }

  // The telemetry series of car `i` in the current part: the part's car series in order.
  function seriesOf(i) {
    const own = data.series.filter((s) => s.scenario === state.part);
    return own[i] ?? null;
  }

  // The name of car `i` as the telemetry of the first part calls it.
  function carName(i) {
    const s = data.series.filter((x) => x.scenario === data.parts[0])[i];
    return s ? s.car : `car ${i}`;
  }

  // The last row at or before `t` (s), by bisection on the time column.
  function rowAt(series, t) {
    const rows = series.rows;
    let lo = 0;
    let hi = rows.length - 1;
    if (hi < 0) return null;
    while (lo < hi) {
      const mid = (lo + hi + 1) >> 1;
      if ((rows[mid][0] ?? 0) <= t) lo = mid;
      else hi = mid - 1;
    }
    return rows[lo];
  }

  function showValues() {
    const s = seriesOf(state.car);
    const row = s ? rowAt(s, state.time) : null;
    const cells = data.columns.map((c, k) => {
      const v = row ? row[k] : null;
      const text = v === null || v === undefined ? "n/a" : Number(v.toFixed(3)).toString();
      return `<tr><td>${c}</td><td class="num">${text}</td><td>${UNITS[c] ?? ""}</td></tr>`;
    });
    const head = s ? `<tr><th colspan="3">${escapeHtml(s.car)} at ${state.time.toFixed(2)} s</th></tr>` : "";
    ui.values.innerHTML = head + cells.join("");
  }

  function escapeHtml(s) {
    return s.replace(/[&<>"']/g, (c) => `&#${c.charCodeAt(0)};`);
  }

  // Places the camera for the current car: behind it (follow), or keeps the user's orbit
  // around it, moved with it (orbit).
  function placeCamera() {
    const car = cars[state.car];
    if (!car) return;
    car.node.updateWorldMatrix(true, false);
    const centre = car.node.localToWorld(car.centre.clone());
    if (state.mode === "follow") {
      const L = car.length;
      const eye = car.centre.clone().add(new THREE.Vector3(-CHASE.back * L, CHASE.left * L, CHASE.up * L));
      camera.position.copy(car.node.localToWorld(eye));
      camera.up.set(0, 1, 0);
      camera.lookAt(centre);
      controls.target.copy(aimAtBody(car, centre));
    } else {
      const moved = centre.clone().sub(controls.target);
      camera.position.add(moved);
      controls.target.copy(centre);
      controls.update();
    }
  }

  function render() {
    if (state.action) {
      state.action.time = state.time;
      mixer.update(0);
    }
    placeCamera();
    renderer.render(scene, camera);
    ui.time.value = String(state.time);
    ui.clock.textContent = `${state.time.toFixed(2)} s / ${state.duration.toFixed(2)} s`;
    showValues();
  }

  function setPart(name) {
    const clip = clips.find((c) => c.name === name) ?? clips[0];
    if (!clip) return;
    if (state.action) state.action.stop();
    state.part = clip.name;
    state.clip = clip;
    state.action = mixer.clipAction(clip);
    state.action.play();
    state.duration = clip.duration;
    ui.time.max = String(clip.duration);
    ui.part.value = clip.name;
    state.time = Math.min(state.time, clip.duration);
    render();
  }

  function seek(t) {
    state.time = Math.max(0, Math.min(Number(t) || 0, state.duration));
    render();
  }

  function follow(i) {
    if (i >= 0 && i < cars.length) state.car = i;
    ui.car.value = String(state.car);
    render();
  }

  function setMode(mode) {
    state.mode = mode === "orbit" ? "orbit" : "follow";
    controls.enabled = state.mode === "orbit";
    ui.camera.value = state.mode;
    render();
  }

  function setPlaying(playing) {
    state.playing = playing;
    ui.play.textContent = playing ? "pause" : "play";
  }

  let last = null;
  function tick(now) {
    if (last !== null && state.playing && state.duration > 0) {
      state.time += ((now - last) / 1000) * state.speed;
      if (state.time > state.duration) state.time = 0;
    }
    last = now;
    render();
    requestAnimationFrame(tick);
  }

  const ready = new Promise((resolve, reject) => {
    const loader = new THREE.GLTFLoader();
    loader.parse(decodeBase64(el("replay-glb").textContent), "", (gltf) => {
      scene.add(gltf.scene);
      mixer = new THREE.AnimationMixer(gltf.scene);
      clips = gltf.animations;
      const nodes = nodesByIndex(gltf);
      cars = data.cars.map((c) => {
        const node = nodes.get(c.root);
        const body = nodes.get(c.body) ?? node;
        const box = boxIn(node, body);
        const size = box.getSize(new THREE.Vector3());
        return {
          node,
          centre: box.getCenter(new THREE.Vector3()),
          length: Math.max(size.x, 0.1),
          points: pointsIn(node, body, 400),
        };
      });
      for (const c of clips) ui.part.add(new Option(c.name, c.name));
      cars.forEach((_, i) => ui.car.add(new Option(carName(i), String(i))));
      resize();
      setPart(data.parts.find((p) => clips.some((c) => c.name === p)));
      resolve();
      requestAnimationFrame(tick);
    }, (error) => {
      ui.viewer.textContent = `The replay could not be loaded: ${error}`;
      console.error(error);
      reject(error);
    });
  });

  ui.part.addEventListener("change", () => setPart(ui.part.value));
  ui.play.addEventListener("click", () => setPlaying(!state.playing));
  ui.time.addEventListener("input", () => { setPlaying(false); seek(ui.time.value); });
  ui.speed.addEventListener("change", () => { state.speed = Number(ui.speed.value); });
  ui.car.addEventListener("change", () => follow(Number(ui.car.value)));
  ui.camera.addEventListener("change", () => setMode(ui.camera.value));
  window.addEventListener("resize", () => { resize(); render(); });

  // The hook of the browser check (and of anyone scripting the page).
  window.report = {
    ready,
    data,
    seek,
    follow,
    setPart,
    camera: setMode,
    play: () => setPlaying(true),
    pause: () => setPlaying(false),
    state: () => ({ time: state.time, duration: state.duration, car: state.car, part: state.part, mode: state.mode }),
  };
})();
