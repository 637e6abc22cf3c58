// The closed forms of a run's motion, where its scene has one, for the viewer's plot of the motion.
// Computed here, in the page, from the scene's parameters (gravity, G, masses, moments, applied
// force and torque) and the state at t = 0 (the scene's initial state: no step has run), apart
// from the engine and its model functions, so that the plot sets the engine's run against an
// independent reference. gpClosedForms(data) gives [{body, quantity, column, at(t)}], column
// indexing a frame's state [x, y, ϕ, vx, vy, ω]; [] when the scene has no closed form.
"use strict";
function gpClosedForms(data) {
  const bodies = data.bodies, start = data.frames.states[0];
  const forceFree = (b) => b.force[0] === 0 && b.force[1] === 0 && b.torque === 0;

  // One body alone (nothing to collide with) under uniform gravity, a constant force at its centre
  // of mass and a constant torque: constant accelerations a = g + F/m (IM:transMot) and α = τ/I
  // (IM:rotMot), so p = p0 + v0 t + a t²/2 and ω = ω0 + α t.
  if (bodies.length === 1 && bodies[0].type === "dynamic" && data.G === null && bodies[0].force_at_com) {
    const b = bodies[0], [x0, y0, , vx0, vy0, w0] = start[0];
    const ax = data.gravity[0] + b.force[0] / b.mass, ay = data.gravity[1] + b.force[1] / b.mass;
    const forms = [];
    if (vx0 !== 0 || vy0 !== 0 || ax !== 0 || ay !== 0) {
      forms.push({ body: 0, quantity: "x", column: 0, at: (t) => x0 + vx0 * t + 0.5 * ax * t * t },
        { body: 0, quantity: "y", column: 1, at: (t) => y0 + vy0 * t + 0.5 * ay * t * t });
    }
    if (b.moment !== null && (w0 !== 0 || b.torque !== 0)) {
      const alpha = b.torque / b.moment;
      forms.push({ body: 0, quantity: "ω", column: 5, at: (t) => w0 + alpha * t });
    }
    return forms;
  }

  // Two point masses under their mutual gravitation alone (TM:UniversalGravLaw), started on a
  // circle about their centre of mass: no radial relative velocity, a tangential one of Ω d. Each
  // then turns about the centre of mass, which drifts at its initial velocity, at
  // Ω = √(G (m₁ + m₂) / d³).
  const zeroGravity = data.gravity[0] === 0 && data.gravity[1] === 0;
  if (bodies.length === 2 && data.G !== null && zeroGravity &&
      bodies.every((b) => b.type === "dynamic" && b.shapes.length === 0 && forceFree(b))) {
    const [ma, mb] = bodies.map((b) => b.mass), m = ma + mb;
    const mean = (n) => (ma * start[0][n] + mb * start[1][n]) / m;
    const centre = [mean(0), mean(1)], drift = [mean(3), mean(4)];
    const r = [start[0][0] - start[1][0], start[0][1] - start[1][1]];
    const v = [start[0][3] - start[1][3], start[0][4] - start[1][4]];
    const d = Math.hypot(r[0], r[1]), omega = Math.sqrt((data.G * m) / d ** 3);
    const radial = (r[0] * v[0] + r[1] * v[1]) / d, tangential = (r[0] * v[1] - r[1] * v[0]) / d;
    const speed = omega * d;
    if (Math.abs(radial) > 1e-6 * speed || Math.abs(Math.abs(tangential) - speed) > 1e-6 * speed) return [];
    const turn = Math.sign(tangential) * omega;
    return bodies.flatMap((b, i) => {
      const rx = start[i][0] - centre[0], ry = start[i][1] - centre[1];
      const place = (t) => {
        const c = Math.cos(turn * t), s = Math.sin(turn * t);
        return [centre[0] + drift[0] * t + c * rx - s * ry, centre[1] + drift[1] * t + s * rx + c * ry];
      };
      return [{ body: i, quantity: "x", column: 0, at: (t) => place(t)[0] },
        { body: i, quantity: "y", column: 1, at: (t) => place(t)[1] }];
    });
  }
  return [];
}
