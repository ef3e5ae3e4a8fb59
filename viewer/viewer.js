// newtop view: plays a newtop trajectory in 3D (three.js) beside the drift of its integrals.
// The page's data (the JSON block "newtop-data", written by `newtop view`) holds the CSV's rows and,
// with --scenario, the body. Every vector is in the body's principal axes (docs/model.md §1). With q0..q3
// (body -> inertial, scalar first) the body group turns by that quaternion in a fixed inertial
// frame; without them the body is fixed and the direction to the centre, -gamma(t), moves. An orbit
// run (data.orbit, docs/orbit.md §12) is shown in the body frame with the LVLH triad (x_L = n × γ
// along-track, y_L = −n, z_L = −γ to nadir: docs/orbit.md §11) and the orbit: a circle in the
// plane normal to n through the body, about the centre (not to scale).
// window.newtopView exposes the state for tests and scripting (setTime, state, frames).
(function () {
  "use strict";
  const data = JSON.parse(document.getElementById("newtop-data").textContent);
  const C = data.columns;
  const N = C.t.length;
  const t0 = C.t[0], t1 = C.t[N - 1];
  const $ = (id) => document.getElementById(id);
  const COLORS = { centre: 0xd62728, omega: 0x1f77b4, momentum: 0x2ca02c, trace: 0x9467bd };
  const BODY_RADIUS = 0.7;  // the body is drawn inside the Poisson sphere of radius 1

  const vec = (name, i) => new THREE.Vector3(C[name + "1"][i], C[name + "2"][i], C[name + "3"][i]);
  const gammaAt = (i) => vec("gamma", i);
  const omegaAt = (i) => new THREE.Vector3(C.p[i], C.q[i], C.r[i]);
  const quatAt = (i) => new THREE.Quaternion(C.q1[i], C.q2[i], C.q3[i], C.q0[i]).normalize();
  const body = data.body;
  const momentumOf = (w) => body ? new THREE.Vector3(
      body.inertia[0] * w.x + body.gyrostat[0], body.inertia[1] * w.y + body.gyrostat[1],
      body.inertia[2] * w.z + body.gyrostat[2]) : null;

  // --- header and notes ---------------------------------------------------------------------
  $("title").textContent = "newtop view: " + data.source + (data.scenario ? "  (" + data.scenario + ")" : "");
  $("mode").textContent = data.orbit
      ? "body frame on an orbit: the LVLH triad (x_L along-track, y_L = −n, z_L to nadir) and the " +
        "orbit (a circle about the centre, not to scale) turn around the body"
      : data.attitude
      ? "inertial frame: the body turns by its attitude q0..q3 (body → inertial)"
      : "body frame: no attitude columns (q0..q3) in this CSV, so the body is held fixed and the " +
        "direction to the centre −γ(t) moves around it";
  const notes = [];
  if (!body) notes.push("No --scenario: the body is drawn as a sphere with its axes, and the " +
                        "angular momentum (needs I and k) is not shown.");
  if (data.rows_shown < data.rows_total)
    notes.push("Showing " + data.rows_shown + " of " + data.rows_total + " rows (evenly spaced).");
  if (body && body.shape.kind !== "inertia_ellipsoid")
    notes.push("Body: its " + body.shape.kind + " mass model, scaled to fit the sphere.");
  if (body && body.shape.kind === "inertia_ellipsoid")
    notes.push("Body: its inertia ellipsoid x·Ix = 1 (semi-axes ∝ 1/√A, 1/√B, 1/√C), scaled.");
  $("notes").textContent = notes.join(" ");
  if (!body) $("legend").children[2].style.display = "none";

  // --- scene --------------------------------------------------------------------------------
  const host = $("scene");
  const renderer = new THREE.WebGLRenderer({ antialias: true, preserveDrawingBuffer: true });
  renderer.setPixelRatio(window.devicePixelRatio || 1);
  renderer.setClearColor(0xffffff, 1);
  host.appendChild(renderer.domElement);
  const scene = new THREE.Scene();
  const camera = new THREE.PerspectiveCamera(40, 1, 0.01, 100);
  camera.up.set(0, 0, 1);
  camera.position.set(3.2, 2.2, 1.8);
  const controls = new THREE.OrbitControls(camera, renderer.domElement);
  controls.addEventListener("change", () => draw());
  scene.add(new THREE.AmbientLight(0xffffff, 0.55));
  const sun = new THREE.DirectionalLight(0xffffff, 0.7);
  sun.position.set(3, 2, 4);
  scene.add(sun);

  function line(points, color, opacity) {
    const g = new THREE.BufferGeometry().setFromPoints(points);
    const m = new THREE.LineBasicMaterial({ color: color, transparent: opacity < 1, opacity: opacity });
    return new THREE.Line(g, m);
  }
  function label(text, position, color) {
    const c = document.createElement("canvas");
    c.width = c.height = 64;
    const g = c.getContext("2d");
    g.fillStyle = color;
    g.font = "bold 44px sans-serif";
    g.textAlign = "center";
    g.textBaseline = "middle";
    g.fillText(text, 32, 34);
    const s = new THREE.Sprite(new THREE.SpriteMaterial({ map: new THREE.CanvasTexture(c) }));
    s.position.copy(position);
    s.scale.set(0.14, 0.14, 1);
    return s;
  }
  function axes(group, length, color) {
    ["x", "y", "z"].forEach((n, i) => {
      const e = new THREE.Vector3(i === 0, i === 1, i === 2).multiplyScalar(length);
      group.add(line([new THREE.Vector3(), e], color, 1));
      group.add(label(n, e.clone().multiplyScalar(1.08), "#555"));
    });
  }

  // Inertial reference (only meaningful when the body turns): faint axes X, Y, Z.
  if (data.attitude) {
    ["X", "Y", "Z"].forEach((n, i) => {
      const e = new THREE.Vector3(i === 0, i === 1, i === 2).multiplyScalar(1.9);
      scene.add(line([e.clone().negate(), e], 0xbbbbbb, 1));
      scene.add(label(n, e.clone().multiplyScalar(1.05), "#aaa"));
    });
  }

  // The body group carries everything fixed in the body: shape, axes, Poisson sphere, trace of gamma
  // and the body-frame vectors (so that in the inertial view they turn with it).
  const bodyGroup = new THREE.Group();
  scene.add(bodyGroup);
  bodyGroup.add(makeShape());
  axes(bodyGroup, 1.15, 0x666666);

  const sphere = new THREE.Mesh(new THREE.SphereBufferGeometry(1, 48, 24),
      new THREE.MeshBasicMaterial({ color: 0x9467bd, wireframe: true, transparent: true, opacity: 0.08 }));
  bodyGroup.add(sphere);
  const tracePoints = [];
  for (let i = 0; i < N; ++i) tracePoints.push(gammaAt(i).normalize());
  bodyGroup.add(line(tracePoints, COLORS.trace, 0.25));         // the whole path, faint
  const trace = line(tracePoints, COLORS.trace, 1);             // the part already travelled
  bodyGroup.add(trace);
  const gammaDot = new THREE.Mesh(new THREE.SphereBufferGeometry(0.03, 16, 8),
                                  new THREE.MeshBasicMaterial({ color: COLORS.trace }));
  bodyGroup.add(gammaDot);

  // An arrow along +Y of unit length: a shaft and a cone, turned and stretched by setArrow.
  const Y = new THREE.Vector3(0, 1, 0);
  function makeArrow(color, radius) {
    const m = new THREE.MeshPhongMaterial({ color: color, shininess: 30 });
    const arrow = new THREE.Group();
    arrow.shaft = new THREE.Mesh(new THREE.CylinderBufferGeometry(radius, radius, 1, 12), m);
    arrow.head = new THREE.Mesh(new THREE.ConeBufferGeometry(2.6 * radius, 1, 16), m);
    arrow.add(arrow.shaft, arrow.head);
    return arrow;
  }
  const centreArrow = makeArrow(COLORS.centre, 0.02);
  const omegaArrow = makeArrow(COLORS.omega, 0.016);
  const momentumArrow = makeArrow(COLORS.momentum, 0.016);
  bodyGroup.add(centreArrow, omegaArrow);
  if (body) bodyGroup.add(momentumArrow);

  // --- orbit runs: the LVLH triad and the orbit, in the body frame ---------------------------
  const LVLH_COLORS = ["#ff7f0e", "#17becf", "#8c564b"];  // x_L, y_L, z_L
  const RING = 1.6;  // the centre at the tip of the centre arrow; the orbit through the body
  const lvlhArrows = [], lvlhLabels = [];
  let orbitRing = null;
  const normalAt = (i) => vec("normal", i);
  if (data.orbit) {
    ["xL", "yL", "zL"].forEach((name, i) => {
      const a = makeArrow(new THREE.Color(LVLH_COLORS[i]).getHex(), 0.012);
      const l = label(name, new THREE.Vector3(), LVLH_COLORS[i]);
      bodyGroup.add(a, l);
      lvlhArrows.push(a);
      lvlhLabels.push(l);
    });
    const points = [];
    for (let k = 0; k <= 128; ++k) points.push(new THREE.Vector3());
    orbitRing = line(points, 0x444444, 0.7);
    bodyGroup.add(orbitRing);
  }
  // C(body←LVLH)'s columns, the LVLH axes in body components: n × γ, −n, −γ.
  const lvlhTriad = (g, n) => [n.clone().cross(g), n.clone().negate(), g.clone().negate()];
  let shownTriad = null;
  function showOrbit(g, n) {
    shownTriad = lvlhTriad(g, n);
    shownTriad.forEach((v, i) => {
      setArrow(lvlhArrows[i], v, 1.0);
      lvlhLabels[i].position.copy(v).multiplyScalar(1.1);
    });
    const pos = orbitRing.geometry.attributes.position;
    const along = shownTriad[0];
    for (let k = 0; k < pos.count; ++k) {
      const s = 2 * Math.PI * k / (pos.count - 1);
      const p = g.clone().multiplyScalar(RING * (Math.cos(s) - 1))
                    .add(along.clone().multiplyScalar(RING * Math.sin(s)));
      pos.setXYZ(k, p.x, p.y, p.z);
    }
    pos.needsUpdate = true;
  }

  let maxOmega = 0, maxMomentum = 0;
  for (let i = 0; i < N; ++i) {
    const w = omegaAt(i);
    maxOmega = Math.max(maxOmega, w.length());
    if (body) maxMomentum = Math.max(maxMomentum, momentumOf(w).length());
  }

  function makeShape() {
    const material = new THREE.MeshPhongMaterial({ color: 0xc8b48a, flatShading: true,
                                                   side: THREE.DoubleSide, shininess: 20 });
    if (!body) return new THREE.Mesh(new THREE.SphereBufferGeometry(0.25, 32, 16), material);
    const s = body.shape;
    if (s.kind === "mesh") {
      const g = new THREE.BufferGeometry();
      g.setAttribute("position", new THREE.Float32BufferAttribute(s.vertices, 3));
      g.setIndex(s.faces);
      g.computeVertexNormals();
      g.computeBoundingSphere();
      return fit(new THREE.Mesh(g, material), s.radius);
    }
    if (s.kind === "ellipsoid") {
      const m = new THREE.Mesh(new THREE.SphereBufferGeometry(1, 48, 24), material);
      m.scale.set(s.semi_axes[0], s.semi_axes[1], s.semi_axes[2]);
      m.position.set(s.center[0], s.center[1], s.center[2]);
      const holder = new THREE.Group();
      const P = new THREE.Matrix4();  // rows of P^T: user frame -> body frame
      const a = s.to_body;
      P.set(a[0][0], a[0][1], a[0][2], 0, a[1][0], a[1][1], a[1][2], 0, a[2][0], a[2][1], a[2][2], 0,
            0, 0, 0, 1);
      holder.applyMatrix(P);
      holder.add(m);
      return fit(holder, s.radius);
    }
    if (s.kind === "points") {
      const holder = new THREE.Group();
      const mmax = Math.max.apply(null, s.masses);
      s.masses.forEach((mass, i) => {
        const ball = new THREE.Mesh(new THREE.SphereBufferGeometry(1, 16, 8), material);
        ball.scale.setScalar(0.08 * s.radius * Math.cbrt(mass / mmax) / BODY_RADIUS);
        ball.position.fromArray(s.positions, 3 * i);
        holder.add(ball);
      });
      return fit(holder, s.radius);
    }
    // inertia ellipsoid x·Ix = 1: semi-axes 1/sqrt(A), 1/sqrt(B), 1/sqrt(C)
    const m = new THREE.Mesh(new THREE.SphereBufferGeometry(1, 48, 24), material);
    const r = body.inertia.map((I) => 1 / Math.sqrt(I));
    const k = BODY_RADIUS / Math.max.apply(null, r);
    m.scale.set(k * r[0], k * r[1], k * r[2]);
    return m;
  }
  function fit(object, radius) {
    const g = new THREE.Group();
    g.add(object);
    g.scale.setScalar(BODY_RADIUS / radius);
    return g;
  }

  // --- time ---------------------------------------------------------------------------------
  let time = t0, playing = false, lastWall = null, index = 0;
  const slider = $("slider");
  slider.min = String(t0);
  slider.max = String(t1);
  slider.value = String(t0);

  function segment(t) {  // largest k with C.t[k] <= t
    let lo = 0, hi = N - 1;
    if (t >= C.t[hi]) return hi;
    while (hi - lo > 1) {
      const mid = (lo + hi) >> 1;
      if (C.t[mid] <= t) lo = mid; else hi = mid;
    }
    return lo;
  }
  function setArrow(arrow, v, length) {
    const n = v.length();
    arrow.visible = n > 0 && length > 0;
    if (!arrow.visible) return;
    arrow.quaternion.setFromUnitVectors(Y, v.clone().divideScalar(n));
    const head = Math.min(0.14, 0.35 * length);
    arrow.shaft.scale.set(1, length - head, 1);
    arrow.shaft.position.set(0, (length - head) / 2, 0);
    arrow.head.scale.set(1, head, 1);
    arrow.head.position.set(0, length - head / 2, 0);
  }
  function apply(t) {
    time = Math.min(Math.max(t, t0), t1);
    const k = segment(time);
    index = k;
    const w = k < N - 1 ? (time - C.t[k]) / (C.t[k + 1] - C.t[k]) : 0;
    let g = gammaAt(k), om = omegaAt(k);
    if (w > 0) {
      g.lerp(gammaAt(k + 1), w).normalize();
      om.lerp(omegaAt(k + 1), w);
    }
    if (data.attitude) {
      const q = quatAt(k);
      if (w > 0) q.slerp(quatAt(k + 1), w);
      bodyGroup.quaternion.copy(q);
    }
    setArrow(centreArrow, g.clone().negate(), 1.6);
    setArrow(omegaArrow, om, maxOmega > 0 ? 1.4 * om.length() / maxOmega : 0);
    if (body) {
      const m = momentumOf(om);
      setArrow(momentumArrow, m, maxMomentum > 0 ? 1.4 * m.length() / maxMomentum : 0);
    }
    if (data.orbit) {
      const n = normalAt(k);
      if (w > 0) n.lerp(normalAt(k + 1), w).normalize();
      showOrbit(g, n);
    }
    gammaDot.position.copy(g);
    trace.geometry.setDrawRange(0, k + 1);
    slider.value = String(time);
    $("clock").textContent = "t = " + time.toPrecision(8) + "  (row " + (k + 1) + " of " + N + ")";
    showState(k, g, om);
    window.NewtopDrift.cursor(time);
    draw();
  }
  function showState(k, g, om) {
    const f = (v) => v.toPrecision(6);
    const rows = [["ω", [om.x, om.y, om.z].map(f).join(", ")], ["γ", [g.x, g.y, g.z].map(f).join(", ")]];
    if (data.attitude) {
      const q = bodyGroup.quaternion;
      rows.push(["q", [q.w, q.x, q.y, q.z].map(f).join(", ")]);
    }
    if (data.orbit && C.roll) {
      rows.push(["roll, pitch, yaw", [C.roll[k], C.pitch[k], C.yaw[k]].map(f).join(", ")]);
    }
    Object.keys(data.integrals).forEach((n) => rows.push([n, data.integrals[n][k].toPrecision(12)]));
    $("state").innerHTML = "";
    rows.forEach(([a, b]) => {
      const tr = $("state").insertRow();
      tr.insertCell().textContent = a;
      tr.insertCell().textContent = b;
    });
  }
  function draw() { renderer.render(scene, camera); }
  function resize() {
    const w = host.clientWidth, h = host.clientHeight;
    if (w === 0 || h === 0) return;
    renderer.setSize(w, h, false);
    camera.aspect = w / h;
    camera.updateProjectionMatrix();
    draw();
  }

  const baseRate = (t1 - t0) / 20;  // the whole run in 20 s at 1x
  function tick(now) {
    if (playing) {
      if (lastWall !== null) {
        const next = time + (now - lastWall) / 1000 * baseRate * Number($("speed").value);
        apply(next >= t1 ? t1 : next);
        if (next >= t1) setPlaying(false);
      }
      lastWall = now;
    }
    requestAnimationFrame(tick);
  }
  function setPlaying(on) {
    playing = on;
    lastWall = null;
    if (on && time >= t1) apply(t0);
    $("play").textContent = on ? "Pause" : "Play";
  }
  $("play").addEventListener("click", () => setPlaying(!playing));
  slider.addEventListener("input", () => { setPlaying(false); apply(Number(slider.value)); });
  document.addEventListener("keydown", (e) => {
    if (e.key === " ") { e.preventDefault(); setPlaying(!playing); }
  });
  if (window.ResizeObserver) new ResizeObserver(resize).observe(host);
  window.addEventListener("resize", resize);

  window.NewtopDrift.init($("drift"), C.t, data.integrals);
  resize();
  apply(t0);
  requestAnimationFrame(tick);

  // State for tests and scripting: what the scene shows, read back from the three.js objects.
  window.newtopView = {
    frames: N,
    times: C.t,
    attitude: data.attitude,
    orbit: data.orbit,
    setTime: (t) => { setPlaying(false); apply(t); },
    play: () => setPlaying(true),
    pause: () => setPlaying(false),
    state: () => {
      const q = bodyGroup.quaternion;
      const d = new THREE.Vector3(0, 1, 0).applyQuaternion(centreArrow.quaternion)
                    .applyQuaternion(bodyGroup.quaternion);
      const out = { t: time, index: index, playing: playing,
                    body_quaternion: [q.w, q.x, q.y, q.z], centre_direction: [d.x, d.y, d.z] };
      if (data.orbit) {  // the LVLH axes as drawn (arrow directions), body components
        out.lvlh = lvlhArrows.map((a) => {
          const v = new THREE.Vector3(0, 1, 0).applyQuaternion(a.quaternion);
          return [v.x, v.y, v.z];
        });
        const pos = orbitRing.geometry.attributes.position;
        out.orbit_points = [0, 32, 64].map((k) => [pos.getX(k), pos.getY(k), pos.getZ(k)]);
      }
      return out;
    },
    ready: true,
  };
})();
