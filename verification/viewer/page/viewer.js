// The viewer of `gamephysics view`: plays back the recorded run embedded in #gp-data.
// Data layout (verification/viewer/viewer_page.cpp): frames.states[k][body] = [x, y, ϕ, vx, vy, ω],
// frames.quantities[k][body] and frames.totals[k] = [KE_trans, KE_rot, PE, px, py, L],
// frames.contacts[k] = [[a, b, x, y, nx, ny, impulse]], impacts = [{t, a, b, normal, point, j, dv_a, dv_b}].
"use strict";
(() => {
  const data = JSON.parse(document.getElementById("gp-data").textContent);
  const frames = data.frames;
  const times = frames.t;
  const bodies = data.bodies;
  const count = times.length;
  const $ = (id) => document.getElementById(id);
  const world = $("world");
  const ctx = world.getContext("2d");

  // One colour per dynamic body; static and kinematic bodies in greys.
  const palette = [[31, 119, 180], [255, 127, 14], [44, 160, 44], [214, 39, 40], [148, 103, 189],
    [140, 86, 75], [227, 119, 194], [188, 189, 34], [23, 190, 207], [127, 127, 127]];
  const colours = bodies.map((b, i) =>
    b.type === "static" ? [150, 150, 150] : b.type === "kinematic" ? [90, 90, 90] : palette[i % palette.length]);
  const rgb = (c, alpha = 1) => `rgba(${c[0]},${c[1]},${c[2]},${alpha})`;

  const place = (state, p) => {
    const c = Math.cos(state[2]), s = Math.sin(state[2]);
    return [state[0] + c * p[0] - s * p[1], state[1] + s * p[0] + c * p[1]];
  };

  // The view: every shape at every frame fits, y up, the same scale on both axes.
  const view = (() => {
    let x0 = Infinity, x1 = -Infinity, y0 = Infinity, y1 = -Infinity;
    const grow = (p, r) => {
      x0 = Math.min(x0, p[0] - r); x1 = Math.max(x1, p[0] + r);
      y0 = Math.min(y0, p[1] - r); y1 = Math.max(y1, p[1] + r);
    };
    for (let k = 0; k < count; ++k) {
      bodies.forEach((b, i) => {
        const st = frames.states[k][i];
        if (b.shapes.length === 0) grow(st, 0);
        for (const sh of b.shapes) {
          if (sh.kind === "circle") grow(place(st, sh.center), sh.radius);
          else if (sh.kind === "polygon") sh.vertices.forEach((v) => grow(place(st, v), 0));
          else { grow(place(st, sh.a), sh.radius); grow(place(st, sh.b), sh.radius); }
        }
      });
    }
    if (!isFinite(x0)) { x0 = -1; x1 = 1; y0 = -1; y1 = 1; }
    const w = Math.max(x1 - x0, 1e-3), h = Math.max(y1 - y0, 1e-3);
    const scale = 0.92 * Math.min(world.width / w, world.height / h);
    return { scale, cx: (x0 + x1) / 2, cy: (y0 + y1) / 2 };
  })();
  const toScreen = (x, y) => [world.width / 2 + (x - view.cx) * view.scale,
    world.height / 2 - (y - view.cy) * view.scale];
  const toWorld = (sx, sy) => [view.cx + (sx - world.width / 2) / view.scale,
    view.cy - (sy - world.height / 2) / view.scale];

  // Arrow scales: the fastest body's velocity is 80 px long, the largest impulse 60 px.
  let maxSpeed = 0, maxImpulse = 0, maxContact = 0;
  for (let k = 0; k < count; ++k) {
    for (const s of frames.states[k]) maxSpeed = Math.max(maxSpeed, Math.hypot(s[3], s[4]));
    for (const c of frames.contacts[k]) maxContact = Math.max(maxContact, c[6]);
  }
  for (const i of data.impacts) maxImpulse = Math.max(maxImpulse, i.j);
  const velocityScale = maxSpeed > 0 ? 80 / maxSpeed : 0;  // px per m/s
  const impulseScale = maxImpulse > 0 ? 60 / maxImpulse : 0;  // px per N·s
  const contactScale = maxContact > 0 ? 30 / maxContact : 0;

  const state = { frame: 0, playing: false, simTime: 0, speed: 1, last: null, selected: null };
  const show = (id) => $(id).checked;

  function arrow(from, vector, scale, colour, width = 2) {
    const [sx, sy] = toScreen(from[0], from[1]);
    const ex = sx + vector[0] * scale, ey = sy - vector[1] * scale;
    const len = Math.hypot(ex - sx, ey - sy);
    if (len < 1) return;
    ctx.strokeStyle = colour; ctx.fillStyle = colour; ctx.lineWidth = width;
    ctx.beginPath(); ctx.moveTo(sx, sy); ctx.lineTo(ex, ey); ctx.stroke();
    const head = Math.min(8, len / 2), a = Math.atan2(ey - sy, ex - sx);
    ctx.beginPath(); ctx.moveTo(ex, ey);
    ctx.lineTo(ex - head * Math.cos(a - 0.4), ey - head * Math.sin(a - 0.4));
    ctx.lineTo(ex - head * Math.cos(a + 0.4), ey - head * Math.sin(a + 0.4));
    ctx.closePath(); ctx.fill();
  }

  // The path of a shape at `st` ([x, y, ϕ]); segments are stroked, the others filled.
  function shapePath(sh, st) {
    ctx.beginPath();
    if (sh.kind === "circle") {
      const [x, y] = toScreen(...place(st, sh.center));
      ctx.arc(x, y, sh.radius * view.scale, 0, 2 * Math.PI);
    } else if (sh.kind === "polygon") {
      sh.vertices.forEach((v, n) => {
        const [x, y] = toScreen(...place(st, v));
        if (n === 0) ctx.moveTo(x, y); else ctx.lineTo(x, y);
      });
      ctx.closePath();
    } else {
      ctx.moveTo(...toScreen(...place(st, sh.a)));
      ctx.lineTo(...toScreen(...place(st, sh.b)));
    }
  }

  function drawBody(i, st, ghost) {
    const b = bodies[i], c = colours[i];
    if (b.shapes.length === 0) {  // a point mass: a dot of fixed size; the oracle's ring around it
      const [x, y] = toScreen(st[0], st[1]);
      ctx.beginPath(); ctx.arc(x, y, ghost ? 11 : 7, 0, 2 * Math.PI);
      if (ghost) { ctx.setLineDash([3, 3]); ctx.strokeStyle = "rgba(0,0,0,0.7)"; ctx.lineWidth = 1.5; ctx.stroke(); ctx.setLineDash([]); }
      else { ctx.fillStyle = rgb(c); ctx.fill(); }
    }
    for (const sh of b.shapes) {
      shapePath(sh, st);
      if (sh.kind === "segment") {
        ctx.lineCap = "round";
        ctx.lineWidth = Math.max(2, 2 * sh.radius * view.scale);
        ctx.strokeStyle = ghost ? "rgba(0,0,0,0.6)" : rgb(c);
        ctx.setLineDash(ghost ? [4, 4] : []);
        ctx.stroke();
      } else if (ghost) {
        ctx.setLineDash([4, 4]); ctx.lineWidth = 1.5; ctx.strokeStyle = "rgba(0,0,0,0.7)"; ctx.stroke();
      } else {
        ctx.fillStyle = rgb(c); ctx.fill();
        ctx.setLineDash([]); ctx.lineWidth = 1; ctx.strokeStyle = "rgba(0,0,0,0.5)"; ctx.stroke();
        if (sh.kind === "circle") {  // a radius fixed in the body shows its rotation
          const [x0, y0] = toScreen(...place(st, sh.center));
          const [x1, y1] = toScreen(...place(st, [sh.center[0] + sh.radius, sh.center[1]]));
          ctx.beginPath(); ctx.moveTo(x0, y0); ctx.lineTo(x1, y1); ctx.stroke();
        }
      }
      ctx.setLineDash([]);
    }
  }

  // A scale bar in the lower left corner: the longest round length (1, 2 or 5 × 10^n m) within
  // 120 px.
  const scaleBar = (() => {
    const most = 120 / view.scale, decade = 10 ** Math.floor(Math.log10(most));
    const metres = [5, 2, 1].map((m) => m * decade).find((l) => l <= most);
    return { metres, pixels: metres * view.scale };
  })();
  function drawScaleBar() {
    const x = 12, y = world.height - 14;
    ctx.strokeStyle = "#333"; ctx.fillStyle = "#333"; ctx.lineWidth = 2;
    ctx.beginPath(); ctx.moveTo(x, y - 5); ctx.lineTo(x, y); ctx.lineTo(x + scaleBar.pixels, y);
    ctx.lineTo(x + scaleBar.pixels, y - 5); ctx.stroke();
    ctx.font = "12px sans-serif";
    ctx.fillText(`${Number(scaleBar.metres.toPrecision(1))} m`, x + scaleBar.pixels + 6, y + 2);
  }

  // Each body's whole path by its closed form (the parabola, the circle), dashed, labelled at its end.
  function drawClosedFormPaths() {
    const paths = bodies.map((b, i) => [closedForms.find((f) => f.body === i && f.quantity === "x"),
      closedForms.find((f) => f.body === i && f.quantity === "y")]).filter(([x, y]) => x && y);
    for (const [x, y] of paths) {
      ctx.beginPath();
      times.forEach((t, k) => { const [sx, sy] = toScreen(x.at(t), y.at(t)); if (k === 0) ctx.moveTo(sx, sy); else ctx.lineTo(sx, sy); });
      ctx.strokeStyle = "rgba(0,0,0,0.55)"; ctx.lineWidth = 1; ctx.setLineDash([5, 4]); ctx.stroke(); ctx.setLineDash([]);
      const [ex, ey] = toScreen(x.at(times[count - 1]), y.at(times[count - 1]));
      ctx.fillStyle = "rgba(0,0,0,0.7)"; ctx.font = "11px sans-serif"; ctx.fillText("closed form", ex + 6, ey - 6);
    }
  }

  let impulseArrows = [];  // those of the last frame drawn, for the tests
  function drawWorld() {
    const k = state.frame;
    impulseArrows = [];
    ctx.clearRect(0, 0, world.width, world.height);
    const states = frames.states[k];
    if (show("show-trails")) {
      bodies.forEach((b, i) => {
        if (b.type !== "dynamic") return;
        ctx.beginPath();
        for (let f = 0; f <= k; ++f) {
          const [x, y] = toScreen(frames.states[f][i][0], frames.states[f][i][1]);
          if (f === 0) ctx.moveTo(x, y); else ctx.lineTo(x, y);
        }
        ctx.strokeStyle = rgb(colours[i], 0.4); ctx.lineWidth = 1; ctx.stroke();
      });
    }
    if (show("show-closed-form")) drawClosedFormPaths();
    bodies.forEach((b, i) => drawBody(i, states[i], false));
    if (data.oracle && show("show-oracle")) {
      bodies.forEach((b, i) => { if (b.type === "dynamic") drawBody(i, data.oracle.states[k][i], true); });
    }
    bodies.forEach((b, i) => {
      if (b.type !== "dynamic") return;
      const st = states[i];
      if (show("show-com")) {
        const [x, y] = toScreen(st[0], st[1]);
        ctx.fillStyle = "#000"; ctx.beginPath(); ctx.arc(x, y, 2.5, 0, 2 * Math.PI); ctx.fill();
      }
      if (show("show-velocity")) arrow(st, [st[3], st[4]], velocityScale, "#1a1a1a", 1.5);
      if (state.selected === i) {
        ctx.strokeStyle = "#000"; ctx.lineWidth = 2; ctx.setLineDash([2, 3]);
        for (const sh of b.shapes) { shapePath(sh, st); ctx.stroke(); }
        ctx.setLineDash([]);
      }
    });
    if (show("show-contacts")) {
      for (const c of frames.contacts[k]) {
        const [x, y] = toScreen(c[2], c[3]);
        ctx.fillStyle = "#0a7"; ctx.beginPath(); ctx.arc(x, y, 3, 0, 2 * Math.PI); ctx.fill();
        arrow([c[2], c[3]], [c[4] * c[6], c[5] * c[6]], contactScale, "#0a7", 1.5);
      }
      // Impacts of the last 0.3 s, fading: the point, and J = j n on A and −J on B (GD:impulse).
      // The impulse on the selected body, or with none selected on a dynamic body, is the bold
      // one: a static ground's points out of the picture and moves nothing.
      for (const im of data.impacts) {
        const age = times[k] - im.t;
        if (age < 0 || age > 0.3) continue;
        const alpha = 1 - age / 0.3;
        const [x, y] = toScreen(im.point[0], im.point[1]);
        ctx.fillStyle = `rgba(200,0,0,${alpha})`;
        ctx.beginPath(); ctx.arc(x, y, 4, 0, 2 * Math.PI); ctx.fill();
        const J = [im.j * im.normal[0], im.j * im.normal[1]];
        for (const [body, sign] of [[im.a, 1], [im.b, -1]]) {
          const bold = state.selected !== null ? state.selected === body : bodies[body].type === "dynamic";
          arrow(im.point, [sign * J[0], sign * J[1]], impulseScale,
            bold ? `rgba(200,0,0,${alpha})` : `rgba(200,0,0,${0.3 * alpha})`, bold ? 3 : 1);
          impulseArrows.push({ body: bodies[body].name, bold });
        }
      }
    }
    drawScaleBar();
  }

  // Round ticks over [lo, hi]: multiples of a step of 1, 2 or 5 × 10^n, about five of them, each
  // computed from its index so that no rounding accumulates (0.30000000000000004).
  function roundTicks(lo, hi) {
    const raw = (hi - lo) / 5, decade = 10 ** Math.floor(Math.log10(raw));
    const step = [1, 2, 5, 10].map((m) => m * decade).find((s) => s >= raw * (1 - 1e-9));
    const digits = Math.max(0, -Math.floor(Math.log10(step)));
    const ticks = [];
    for (let n = Math.ceil(lo / step - 1e-9); n * step <= hi * (1 + 1e-12) + 1e-300; ++n) {
      ticks.push(Number((n * step).toFixed(Math.min(digits, 20))));
    }
    return ticks;
  }
  // An axis label: the tick's round value, in powers of ten when long.
  const axisNumber = (v) =>
    v !== 0 && (Math.abs(v) >= 1e5 || Math.abs(v) < 1e-3) ? v.toExponential(1) : String(v);

  // A line plot of `series` ({label, colour, values, dash}) over time, with the current instant
  // marked; a series with a dash pattern is drawn dashed, one with an empty label has no legend.
  // Linear axes get round ticks, a zero line when 0 is inside and a margin, so that a curve along
  // the top or the bottom stays in sight; log axes get whole decades.
  const drawnTicks = {}, drawnLabels = {};  // per plot, for the tests
  function plot(canvas, series, log) {
    const g = canvas.getContext("2d");
    const W = canvas.width, H = canvas.height, left = 70, right = 10, top = 10, bottom = 38;
    g.clearRect(0, 0, W, H);
    const f = log ? (v) => Math.log10(Math.max(Math.abs(v), 1e-16)) : (v) => v;
    let lo = Infinity, hi = -Infinity;
    for (const s of series) for (const v of s.values) { lo = Math.min(lo, f(v)); hi = Math.max(hi, f(v)); }
    if (!isFinite(lo)) { lo = 0; hi = 1; }
    if (hi - lo < 1e-12 * Math.max(1, Math.abs(hi))) { lo -= 0.5 * Math.max(1, Math.abs(lo)); hi += 0.5 * Math.max(1, Math.abs(hi)); }
    let ticks;
    if (log) {
      lo = Math.floor(lo); hi = Math.max(Math.ceil(hi), lo + 1);
      const every = Math.ceil((hi - lo) / 6);
      ticks = [];
      for (let d = lo; d <= hi; d += every) ticks.push(d);
    } else {
      const margin = 0.05 * (hi - lo);
      lo -= margin; hi += margin;
      ticks = roundTicks(lo, hi);
    }
    drawnTicks[canvas.id] = log ? ticks.map((d) => 10 ** d) : ticks;
    const t0 = times[0], t1 = times[count - 1] > t0 ? times[count - 1] : t0 + 1;
    const px = (t) => left + ((t - t0) / (t1 - t0)) * (W - left - right);
    const py = (v) => top + (1 - (f(v) - lo) / (hi - lo)) * (H - top - bottom);
    const pyAxis = (a) => top + (1 - (a - lo) / (hi - lo)) * (H - top - bottom);
    g.strokeStyle = "#999"; g.lineWidth = 1; g.strokeRect(left, top, W - left - right, H - top - bottom);
    g.fillStyle = "#333"; g.font = "11px sans-serif";
    for (const a of ticks) {
      const y = pyAxis(a);
      g.strokeStyle = "#eee"; g.beginPath(); g.moveTo(left, y); g.lineTo(W - right, y); g.stroke();
      g.fillText(log ? `1e${a}` : axisNumber(a), 4, y + 4);
    }
    for (const t of roundTicks(t0, t1)) g.fillText(`${t} s`, px(t) - 12, H - bottom + 14);
    if (!log && lo < 0 && hi > 0) {
      g.strokeStyle = "#888"; g.setLineDash([4, 3]); g.beginPath();
      g.moveTo(left, py(0)); g.lineTo(W - right, py(0)); g.stroke(); g.setLineDash([]);
    }
    let lx = left + 6;
    drawnLabels[canvas.id] = [];
    for (const s of series) {
      g.strokeStyle = s.colour; g.lineWidth = 1.5; g.setLineDash(s.dash ?? []); g.beginPath();
      s.values.forEach((v, k) => { if (k === 0) g.moveTo(px(times[k]), py(v)); else g.lineTo(px(times[k]), py(v)); });
      g.stroke(); g.setLineDash([]);
      if (!s.label) continue;
      g.fillStyle = s.colour; g.fillText(s.label, lx, H - 6); lx += g.measureText(s.label).width + 14;
      drawnLabels[canvas.id].push(s.label);
    }
    g.strokeStyle = "#c00"; g.beginPath(); g.moveTo(px(times[state.frame]), top);
    g.lineTo(px(times[state.frame]), H - bottom); g.stroke();
  }

  const column = (rows, n) => rows.map((r) => r[n]);
  const totals = frames.totals;
  const energySeries = [
    { label: "KE translational", colour: "#1f77b4", values: column(totals, 0) },
    { label: "KE rotational", colour: "#9467bd", values: column(totals, 1) },
    { label: "PE", colour: "#2ca02c", values: column(totals, 2) },
    { label: "total E", colour: "#000", values: totals.map((r) => r[0] + r[1] + r[2]) },
  ];
  const momentumSeries = [
    { label: "p_x", colour: "#d62728", values: column(totals, 3) },
    { label: "p_y", colour: "#ff7f0e", values: column(totals, 4) },
    { label: "L", colour: "#17becf", values: column(totals, 5) },
  ];
  const errorSeries = data.oracle ? [{
    label: `position error against the oracle (${data.oracle.method})`, colour: "#c00",
    values: times.map((t, k) => Math.max(0, ...bodies.map((b, i) => b.type !== "dynamic" ? 0 :
      Math.hypot(frames.states[k][i][0] - data.oracle.states[k][i][0],
        frames.states[k][i][1] - data.oracle.states[k][i][1])))),
  }] : null;

  // The motion where the scene has a closed form (closed_form.js): the run's x, y or ω, solid, and
  // the closed form's, dashed black over it.
  const closedForms = gpClosedForms(data);
  const motionSeries = [
    ...closedForms.map((f, n) => ({ label: `${f.quantity} ${bodies[f.body].name}`,
      colour: rgb(palette[n % palette.length]), values: column(frames.states.map((s) => s[f.body]), f.column) })),
    ...closedForms.map((f, n) => ({ label: n === 0 ? "closed form (dashed)" : "", colour: "#000",
      dash: [5, 4], values: times.map(f.at) })),
  ];

  const fmt = (v) => (v === null || v === undefined ? "∞" : Math.abs(v) < 1e-300 ? "0" : Number(v.toPrecision(6)).toString());
  const vec = (v) => `(${fmt(v[0])}, ${fmt(v[1])})`;

  // The selected body's state and SRS quantities at the current instant, each with its SRS id.
  function inspect() {
    const table = $("body-table");
    const k = state.frame, i = state.selected;
    $("impact-count").textContent = `${data.impacts.filter((im) => im.t <= times[k]).length} of ${data.impacts.length}`;
    $("no-selection").style.display = i === null ? "" : "none";
    if (i === null) { table.innerHTML = ""; return; }
    const b = bodies[i], st = frames.states[k][i], q = frames.quantities[k][i];
    const rows = [
      ["body", "", `${b.name} (${b.type})`, ""],
      ["time t", "", fmt(times[k]), "s"],
      ["mass m", "DD:ctrOfMass", fmt(b.mass), "kg"],
      ["moment of inertia I", "DD:momentOfInertia", fmt(b.moment), "kg·m²"],
      ["centre of mass p", "DD:ctrOfMass", vec(st), "m"],
      ["orientation ϕ", "IM:rotMot", fmt(st[2]), "rad"],
      ["velocity v", "DD:linVel", vec([st[3], st[4]]), "m/s"],
      ["angular velocity ω", "DD:angVel", fmt(st[5]), "rad/s"],
      ["kinetic energy, translational m‖v‖²/2", "DD:kEnergy", fmt(q[0]), "J"],
      ["kinetic energy, rotational Iω²/2", "DD:kEnergy", fmt(q[1]), "J"],
      ["potential energy −m g·p", "DD:potEnergy", fmt(q[2]), "J"],
      ["linear momentum m v", "", vec([q[3], q[4]]), "kg·m/s"],
      ["angular momentum m p×v + Iω", "", fmt(q[5]), "kg·m²/s"],
    ];
    const last = data.impacts.filter((im) => im.t <= times[k] && (im.a === i || im.b === i)).pop();
    if (last) {
      const onA = last.a === i, sign = onA ? 1 : -1;
      rows.push(
        ["last impact: time t_c", "IM:col2D", fmt(last.t), "s"],
        ["with", "", bodies[onA ? last.b : last.a].name, ""],
        ["normal n (from B to A)", "GD:impulse", vec(last.normal), "1"],
        ["impulse j", "GD:impulse", fmt(last.j), "N·s"],
        ["impulse on this body J = ±j n", "DD:impulseV", vec([sign * last.j * last.normal[0], sign * last.j * last.normal[1]]), "N·s"],
        ["velocity change Δv = J/m", "DD:impulseV", vec(onA ? last.dv_a : last.dv_b), "m/s"]);
    } else {
      rows.push(["last impact", "IM:col2D", "none yet", ""]);
    }
    const touching = frames.contacts[k].filter((c) => c[0] === i || c[1] === i);
    rows.push(["contact points now", "", String(touching.length), ""],
      ["their normal impulses", "", fmt(touching.reduce((s, c) => s + c[6], 0)), "N·s"]);
    if (data.oracle) {
      const o = data.oracle.states[k][i];
      rows.push(["oracle's centre of mass", "", vec(o), "m"],
        ["distance to the oracle's", "", fmt(Math.hypot(st[0] - o[0], st[1] - o[1])), "m"]);
    }
    table.innerHTML = "";
    for (const [label, id, value, unit] of rows) {
      const tr = table.insertRow();
      tr.insertCell().textContent = label;
      const cell = tr.insertCell(); cell.className = "id";
      if (id && data.audit) {  // the entry of the SRS id on the audit page
        const link = cell.appendChild(document.createElement("a"));
        link.href = `${data.audit}#${encodeURIComponent(id)}`; link.textContent = id;
      } else {
        cell.textContent = id;
      }
      const v = tr.insertCell(); v.textContent = value; v.className = "value";
      tr.insertCell().textContent = unit;
    }
  }

  function render() {
    drawWorld();
    plot($("energy-plot"), energySeries, false);
    plot($("momentum-plot"), momentumSeries, false);
    if (errorSeries) plot($("error-plot"), errorSeries, true);
    if (closedForms.length) plot($("motion-plot"), motionSeries, false);
    $("scrub").value = state.frame;
    $("clock").textContent = `t = ${times[state.frame].toFixed(3)} s  frame ${state.frame}/${count - 1}`;
    inspect();
  }

  function setFrame(k) {
    state.frame = Math.max(0, Math.min(count - 1, k));
    state.simTime = times[state.frame];
    render();
  }
  function pause() { state.playing = false; $("play").textContent = "Play"; }
  function play() {
    if (state.frame === count - 1) setFrame(0);
    state.playing = true; state.last = null; $("play").textContent = "Pause";
    requestAnimationFrame(tick);
  }
  function tick(now) {
    if (!state.playing) return;
    if (state.last !== null) state.simTime += ((now - state.last) / 1000) * state.speed;
    state.last = now;
    let k = state.frame;
    while (k + 1 < count && times[k + 1] <= state.simTime) ++k;
    if (k !== state.frame) { state.frame = k; render(); }
    if (k === count - 1) { pause(); return; }
    requestAnimationFrame(tick);
  }

  // The body under a click: a point inside one of its shapes (segments within 5 px).
  function bodyAt(sx, sy) {
    const p = toWorld(sx, sy), k = state.frame;
    for (let i = bodies.length - 1; i >= 0; --i) {
      const st = frames.states[k][i];
      for (const sh of bodies[i].shapes) {
        if (sh.kind === "circle") {
          const c = place(st, sh.center);
          if (Math.hypot(p[0] - c[0], p[1] - c[1]) <= sh.radius) return i;
        } else if (sh.kind === "polygon") {
          const v = sh.vertices.map((q) => place(st, q));
          if (v.every((a, n) => { const b = v[(n + 1) % v.length];
            return (b[0] - a[0]) * (p[1] - a[1]) - (b[1] - a[1]) * (p[0] - a[0]) >= 0; })) return i;
        } else {
          const a = place(st, sh.a), b = place(st, sh.b);
          const d = [b[0] - a[0], b[1] - a[1]];
          const u = Math.max(0, Math.min(1, ((p[0] - a[0]) * d[0] + (p[1] - a[1]) * d[1]) / (d[0] * d[0] + d[1] * d[1])));
          if (Math.hypot(p[0] - a[0] - u * d[0], p[1] - a[1] - u * d[1]) <= sh.radius + 5 / view.scale) return i;
        }
      }
    }
    return null;
  }

  $("description").textContent = data.description;
  $("settings").textContent = `integrator ${data.integrator}, dt = ${fmt(data.dt)} s, ` +
    `${count} frames every ${fmt(data.output_dt)} s to ${fmt(data.duration)} s, ` +
    `g = ${vec(data.gravity)} m/s²${data.G === null ? "" : `, G = ${fmt(data.G)} m³/(kg·s²)`}, ` +
    `${data.impacts.length} impacts; velocity arrows ${velocityScale > 0 ? fmt(1 / velocityScale * 80) : 0} m/s per 80 px`;
  if (!data.oracle) { $("oracle-layer").style.display = "none"; $("oracle-figure").style.display = "none"; }
  if (!closedForms.length) { $("motion-figure").style.display = "none"; $("closed-form-layer").style.display = "none"; }
  const scrub = $("scrub");
  scrub.max = count - 1;
  scrub.addEventListener("input", () => { pause(); setFrame(Number(scrub.value)); });
  $("play").addEventListener("click", () => (state.playing ? pause() : play()));
  $("step").addEventListener("click", () => { pause(); setFrame(state.frame + 1); });
  $("back").addEventListener("click", () => { pause(); setFrame(state.frame - 1); });
  $("speed").addEventListener("change", () => { state.speed = Number($("speed").value); });
  for (const box of document.querySelectorAll("#layers input")) box.addEventListener("change", render);
  world.addEventListener("click", (e) => {
    const r = world.getBoundingClientRect();
    state.selected = bodyAt((e.clientX - r.left) * (world.width / r.width), (e.clientY - r.top) * (world.height / r.height));
    render();
  });
  document.addEventListener("keydown", (e) => {
    if (e.target.tagName === "INPUT" && e.target.type === "range") return;
    if (e.key === " ") { e.preventDefault(); state.playing ? pause() : play(); }
    if (e.key === "ArrowRight") { pause(); setFrame(state.frame + 1); }
    if (e.key === "ArrowLeft") { pause(); setFrame(state.frame - 1); }
  });

  // Fewer than 24 frames a simulated second play as a slideshow at 1×: say so, and how to fix it.
  const framesPerSecond = 1 / data.output_dt;
  if (framesPerSecond < 24) {
    $("note").textContent = `This run has ${Number(framesPerSecond.toPrecision(3))} frames a simulated ` +
      `second, too few for smooth playback at 1×: make the page again with --output-dt 0.02 ` +
      `(gamephysics view SCENE.json --output-dt 0.02 --out PAGE.html).`;
  }

  const index = (name) => bodies.findIndex((b) => b.name === name);
  // For tests and scripts: where things are drawn, in canvas pixels.
  window.gp = {
    frameCount: count,
    frame: () => state.frame,
    times: () => times.slice(),
    time: () => times[state.frame],
    playing: () => state.playing,
    play, pause, setFrame,
    worldToScreen: (x, y) => toScreen(x, y),
    pixelsPerMetre: view.scale,
    bodyColour: (name) => colours[index(name)],
    bodyScreenPosition: (name) => { const s = frames.states[state.frame][index(name)]; return toScreen(s[0], s[1]); },
    select: (name) => { state.selected = index(name) < 0 ? null : index(name); render(); },
    selected: () => (state.selected === null ? null : bodies[state.selected].name),
    scaleBar: () => scaleBar,
    ticks: (id) => drawnTicks[id],
    labels: (id) => drawnLabels[id],
    closedForms: () => closedForms.map((f) => ({ body: bodies[f.body].name, quantity: f.quantity,
      values: times.map(f.at) })),
    impulseArrows: () => impulseArrows,
  };
  // Opened as PAGE.html#t=1.4&body=ball&play: at the frame nearest that instant, with that body
  // selected, playing (each part optional).
  const opening = new URLSearchParams(location.hash.slice(1));
  if (opening.has("t")) {
    const t = Number(opening.get("t"));
    let k = 0;
    times.forEach((tk, n) => { if (Math.abs(tk - t) < Math.abs(times[k] - t)) k = n; });
    state.frame = k; state.simTime = times[k];
  }
  if (opening.has("body") && index(opening.get("body")) >= 0) state.selected = index(opening.get("body"));
  render();
  if (opening.has("play")) play();
})();
