// The viewer page in a real browser: a run of scenes/bouncing_ball.json played, stepped and
// scrubbed, with the ball found where the CSV of `gamephysics simulate` puts it, both by the
// page's test hook and by the colour of the pixels drawn; its inspector's DD:kEnergy against
// the CSV; and a page with the oracle overlaid.
import assert from "node:assert/strict";
import { readFileSync } from "node:fs";
import path from "node:path";
import { test } from "node:test";

import { gamephysics, openPage, out, root } from "./browser.mjs";

const scene = path.join(root, "scenes/bouncing_ball.json");
const ballMass = Math.PI * 0.5 * 0.5;  // a disc of radius 0.5 m at the default 1 kg/m²

// The ball's rows of the CSV: [t, x, y, vx, vy] per output instant.
function csvRows(file, body) {
  const [header, ...lines] = readFileSync(file, "utf8").trim().split("\n");
  assert.equal(header, "t,body,x,y,angle,vx,vy,omega");
  return lines.map((l) => l.split(",")).filter((f) => f[1] === body)
    .map((f) => [f[0], f[2], f[3], f[5], f[6]].map(Number));
}

// Where the page drew the ball: the centroid of the pixels of its fill colour.
async function drawnCentre(page) {
  return page.evaluate(() => {
    const canvas = document.getElementById("world");
    const pixels = canvas.getContext("2d").getImageData(0, 0, canvas.width, canvas.height).data;
    const [r, g, b] = window.gp.bodyColour("ball");
    let n = 0, sx = 0, sy = 0;
    for (let i = 0; i < pixels.length; i += 4) {
      if (pixels[i] === r && pixels[i + 1] === g && pixels[i + 2] === b && pixels[i + 3] === 255) {
        const p = i / 4;
        ++n; sx += (p % canvas.width) + 0.5; sy += Math.floor(p / canvas.width) + 0.5;
      }
    }
    return { n, x: sx / n, y: sy / n };
  });
}

test("the viewer shows the ball where simulate puts it, frame by frame", async () => {
  const csvFile = path.join(out, "browser_ball.csv"), html = path.join(out, "browser_ball.html");
  gamephysics("simulate", scene, "--out", csvFile);
  gamephysics("view", scene, "--out", html);
  const rows = csvRows(csvFile, "ball");
  const { page, requests, errors, close } = await openPage(html);
  try {
    await page.waitForFunction(() => window.gp !== undefined);
    assert.equal(await page.evaluate(() => window.gp.frameCount), rows.length);
    // The ball's fill alone: no centre-of-mass dot, velocity arrow or contact marks over it.
    for (const layer of ["#show-com", "#show-velocity", "#show-contacts"]) await page.uncheck(layer);
    const scale = await page.evaluate(() => window.gp.pixelsPerMetre);
    let worstPixels = 0, worstDrawn = 0;
    const compare = async (what) => {
      const k = await page.evaluate(() => window.gp.frame());
      const [t, x, y] = rows[k];
      assert.equal(await page.evaluate(() => window.gp.time()), t, `${what}: time of frame ${k}`);
      const expected = await page.evaluate(([x, y]) => window.gp.worldToScreen(x, y), [x, y]);
      const hook = await page.evaluate(() => window.gp.bodyScreenPosition("ball"));
      const drawn = await drawnCentre(page);
      const dHook = Math.hypot(hook[0] - expected[0], hook[1] - expected[1]);
      const dDrawn = Math.hypot(drawn.x - expected[0], drawn.y - expected[1]);
      assert.ok(drawn.n > 100, `${what}: the ball is drawn (${drawn.n} pixels)`);
      assert.ok(dHook < 1e-6, `${what}: frame ${k}: hook ${hook} against the CSV's ${expected}`);
      assert.ok(dDrawn < 1.5, `${what}: frame ${k}: drawn at ${drawn.x}, ${drawn.y}, CSV ${expected}`);
      worstPixels = Math.max(worstPixels, dHook);
      worstDrawn = Math.max(worstDrawn, dDrawn);
      return k;
    };
    // Play for at least a second of simulated time (60 frames), then pause.
    await page.selectOption("#speed", "4");
    await page.click("#play");
    await page.waitForFunction(() => window.gp.frame() >= 60);
    await page.click("#play");
    assert.equal(await page.evaluate(() => window.gp.playing()), false);
    const played = await compare("played");
    assert.ok(played >= 60);
    await page.screenshot({ path: path.join(out, "viewer_ball_played.png") });
    for (let n = 0; n < 5; ++n) await page.click("#step");
    assert.equal(await compare("stepped"), played + 5);
    // Scrub to 1.5 s, just after the first bounce (t_c = 1.3917 s), and inspect the ball there.
    await page.$eval("#scrub", (s) => { s.value = "90"; s.dispatchEvent(new Event("input")); });
    assert.equal(await compare("scrubbed"), 90);
    const hook = await page.evaluate(() => window.gp.bodyScreenPosition("ball"));
    await page.mouse.click(...(await page.$eval("#world", (c) => [c.getBoundingClientRect().left, c.getBoundingClientRect().top])).map((v, i) => v + hook[i]));
    const cells = await page.$$eval("#body-table tr", (trs) => trs.map((tr) => [...tr.cells].map((c) => c.textContent)));
    const row = (label) => cells.find((c) => c[0].startsWith(label));
    const [, , , vx, vy] = rows[90];
    const ke = Number(row("kinetic energy, translational")[2]);
    assert.equal(row("kinetic energy, translational")[1], "DD:kEnergy");
    assert.ok(Math.abs(ke - 0.5 * ballMass * (vx * vx + vy * vy)) <= 1e-5 * ke, `DD:kEnergy ${ke}`);
    assert.equal(row("impulse on this body")[1], "DD:impulseV");
    assert.ok(Math.abs(Number(row("last impact: time")[2]) - Math.sqrt((2 * 9.5) / 9.81)) < 1e-5);
    await page.screenshot({ path: path.join(out, "viewer_ball_inspected.png") });
    console.log(`viewer: ${rows.length} frames; hook against CSV: ${worstPixels.toExponential(2)} px; ` +
      `drawn pixels against CSV: ${worstDrawn.toFixed(3)} px = ${(worstDrawn / scale).toExponential(3)} m ` +
      `(${scale.toFixed(2)} px/m)`);
    assert.deepEqual(requests, [], "the page fetches nothing");
    assert.deepEqual(errors, [], "no script error");
  } finally {
    await close();
  }
});

test("the viewer overlays the oracle on the oblique collision", async () => {
  const html = path.join(out, "browser_oblique.html");
  gamephysics("view", path.join(root, "scenes/oblique.json"), "--out", html, "--oracle");
  const { page, requests, errors, close } = await openPage(html);
  try {
    await page.waitForFunction(() => window.gp !== undefined);
    assert.ok(await page.isVisible("#error-plot"));
    assert.ok(await page.isVisible("#show-oracle"));
    await page.$eval("#scrub", (s) => { s.value = s.max; s.dispatchEvent(new Event("input")); });
    await page.screenshot({ path: path.join(out, "viewer_oblique_oracle.png") });
    assert.deepEqual(requests, []);
    assert.deepEqual(errors, []);
  } finally {
    await close();
  }
});

// Whether `v` is a whole multiple of `step`, a round step of 1, 2 or 5 × 10^n.
function roundMultiple(v, step) {
  const mantissa = step / 10 ** Math.floor(Math.log10(step) + 1e-9);
  return [1, 2, 5].some((m) => Math.abs(mantissa - m) < 1e-9) &&
    Math.abs(v / step - Math.round(v / step)) < 1e-9;
}

test("the viewer opens at the instant and body its URL names, and plays with #play", async () => {
  const html = path.join(out, "browser_ball_opening.html");
  gamephysics("view", scene, "--out", html);
  for (const [hash, playing] of [["#t=1.4&body=ball", false], ["#t=1.4&body=ball&play", true]]) {
    const { page, errors, close } = await openPage(html, hash);
    try {
      await page.waitForFunction(() => window.gp !== undefined);
      // Frames every 1/60 s: the nearest to 1.4 s is within half of that (and playing, the page
      // has moved on from there by the time it is asked).
      const t = await page.evaluate(() => window.gp.time());
      assert.ok(t >= 1.4 - 1 / 120 - 1e-12 && (playing || t <= 1.4 + 1 / 120 + 1e-12),
        `${hash}: opened at t = ${t}`);
      assert.equal(await page.evaluate(() => window.gp.selected()), "ball");
      assert.equal(await page.evaluate(() => window.gp.playing()), playing, hash);
      if (playing) await page.waitForFunction((t0) => window.gp.time() > t0, t);
      assert.deepEqual(errors, []);
    } finally {
      await close();
    }
  }
});

test("the viewer's impulses, scale bar and plot ticks read as a lecture needs", async () => {
  const html = path.join(out, "browser_ball_lecture.html");
  gamephysics("view", scene, "--out", html);
  const { page, errors, close } = await openPage(html, "#t=1.4");
  try {
    await page.waitForFunction(() => window.gp !== undefined);
    // 8 ms after the first impact (t_c = 1.3917 s): the ball's impulse is the bold arrow, the
    // static ground's the faint one, unless the ground is selected.
    const arrows = await page.evaluate(() => window.gp.impulseArrows());
    assert.deepEqual(arrows, [{ body: "ground", bold: false }, { body: "ball", bold: true }]);
    await page.evaluate(() => window.gp.select("ground"));
    assert.deepEqual(await page.evaluate(() => window.gp.impulseArrows()),
      [{ body: "ground", bold: true }, { body: "ball", bold: false }]);
    // The scale bar is a round length drawn at the page's scale, within 120 px and more than
    // 120 / 2.5 px (the next round length down is at most 2.5 times shorter).
    const bar = await page.evaluate(() => window.gp.scaleBar());
    const scale = await page.evaluate(() => window.gp.pixelsPerMetre);
    assert.ok(roundMultiple(bar.metres, bar.metres), `scale bar ${bar.metres} m`);
    assert.ok(Math.abs(bar.pixels - bar.metres * scale) < 1e-9 && bar.pixels <= 120 && bar.pixels > 48);
    // Plot ticks: whole multiples of one round step, 0 among them when the axis crosses it.
    for (const id of ["energy-plot", "momentum-plot"]) {
      const ticks = await page.evaluate((id) => window.gp.ticks(id), id);
      const step = ticks[1] - ticks[0];
      assert.ok(ticks.length >= 3 && ticks.every((v) => roundMultiple(v, step)), `${id}: ${ticks}`);
    }
    assert.ok((await page.evaluate(() => window.gp.ticks("momentum-plot"))).includes(0));
    // 60 frames a second: no note about sparse output.
    assert.equal(await page.textContent("#note"), "");
    await page.screenshot({ path: path.join(out, "viewer_ball_lecture.png") });
    assert.deepEqual(errors, []);
  } finally {
    await close();
  }
});

test("the viewer says when the output is too sparse to play smoothly, and its log plot has decades", async () => {
  const html = path.join(out, "browser_oblique_sparse.html");
  // The oblique collision every 0.1 s: 10 frames a second.
  gamephysics("view", path.join(root, "scenes/oblique.json"), "--out", html, "--oracle",
    "--output-dt", "0.1");
  const { page, errors, close } = await openPage(html);
  try {
    await page.waitForFunction(() => window.gp !== undefined);
    assert.match(await page.textContent("#note"), /10 frames a simulated second.*--output-dt 0\.02/);
    const decades = await page.evaluate(() => window.gp.ticks("error-plot"));
    assert.ok(decades.length >= 2 && decades.every((v) => Number.isInteger(Math.log10(v))),
      `error plot ticks ${decades}`);
    assert.deepEqual(errors, []);
  } finally {
    await close();
  }
});

test("with --audit, the inspector's SRS ids link to their entries on the audit page", async () => {
  const dir = path.join(out, "browser_linked");
  gamephysics("audit", "--root", root, "--out", dir);
  const html = path.join(dir, "ball.html");
  gamephysics("view", scene, "--out", html, "--audit", "audit.html");
  const { page, errors, close } = await openPage(html, "#t=1.5&body=ball");
  try {
    await page.waitForFunction(() => window.gp !== undefined);
    const links = await page.$$eval("#body-table td.id a", (as) => as.map((a) => a.getAttribute("href")));
    assert.ok(links.includes("audit.html#DD%3AkEnergy"), `links: ${links}`);
    // Followed, each lands on the audit page's section of that id.
    await page.click('#body-table td.id a[href="audit.html#DD%3AkEnergy"]');
    await page.waitForURL(/audit\.html#DD%3AkEnergy$/);
    assert.equal(await page.locator('[id="DD:kEnergy"].srs-item').count(), 1);
    for (const href of new Set(links)) {
      const id = decodeURIComponent(href.split("#")[1]);
      assert.equal(await page.locator(`[id="${id}"]`).count(), 1, `${id} has an entry`);
    }
    assert.deepEqual(errors, []);
  } finally {
    await close();
  }
});

// The closed forms the page overlays on its plot of the motion, against hand computations from
// the scene files' numbers: the projectile's x = 10 t, y = 10 t − 4.905 t²; the spinning box's
// ω = τ t / I = 0.5 t / (1/6) = 3 t; the orbit's heavy body, 0.5 m from the centre of mass at the
// origin, turning at Ω = √(G (m₁ + m₂) / d³) from (−0.5, 0) (counter-clockwise: its velocity
// points down). A scene with impacts has none, and no plot of it.
test("the viewer overlays the closed form of the motion where the scene has one", async () => {
  const omega = Math.sqrt((6.674e-11 * 4e11) / 8);
  const cases = [
    ["projectile", [["x", "projectile", 1.0, 10.0], ["y", "projectile", 1.0, 10 - 4.905],
      ["y", "projectile", 2.0, 20 - 4.905 * 4]]],
    ["spinning_box", [["ω", "box", 1.0, 3.0], ["ω", "box", 3.0, 9.0]]],
    ["orbit", [["x", "heavy", 1.0, -0.5 * Math.cos(omega)], ["y", "heavy", 1.0, -0.5 * Math.sin(omega)],
      ["x", "light", 2.0, 1.5 * Math.cos(2 * omega)]]],
    ["bouncing_ball", []],
  ];
  for (const [name, expected] of cases) {
    const html = path.join(out, `browser_closed_form_${name}.html`);
    gamephysics("view", path.join(root, `scenes/${name}.json`), "--out", html);
    const { page, errors, close } = await openPage(html, "#t=1");
    try {
      await page.waitForFunction(() => window.gp !== undefined);
      const forms = await page.evaluate(() => window.gp.closedForms());
      const times = await page.evaluate(() => window.gp.times());
      assert.equal(await page.isVisible("#motion-plot"), expected.length > 0, `${name}: the plot`);
      assert.equal(await page.isVisible("#show-closed-form"), expected.length > 0, `${name}: the layer`);
      if (expected.length > 0) {
        const labels = await page.evaluate(() => window.gp.labels("motion-plot"));
        assert.ok(labels.includes("closed form (dashed)"), `${name}: legend ${labels}`);
      } else {
        assert.deepEqual(forms, [], `${name}: no closed form`);
      }
      for (const [quantity, body, t, value] of expected) {
        const form = forms.find((f) => f.quantity === quantity && f.body === body);
        assert.ok(form, `${name}: a closed form of ${quantity} of ${body}`);
        const k = times.findIndex((tk) => Math.abs(tk - t) < 1e-9);
        assert.ok(k >= 0, `${name}: an output instant at ${t} s`);
        assert.ok(Math.abs(form.values[k] - value) <= 1e-9 * Math.max(1, Math.abs(value)),
          `${name}: ${quantity} of ${body} at ${t} s: ${form.values[k]}, by hand ${value}`);
      }
      if (name === "projectile") await page.screenshot({ path: path.join(out, "viewer_closed_form.png"), fullPage: true });
      assert.deepEqual(errors, []);
    } finally {
      await close();
    }
  }
});
