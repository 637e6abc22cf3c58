// The audit page in a real browser: every id of srs/catalog.json has its section, every model's
// equation and symbols are typeset by KaTeX without an error, the four traceability matrices are
// tables, and the page fetches nothing.
import assert from "node:assert/strict";
import { readFileSync } from "node:fs";
import path from "node:path";
import { test } from "node:test";

import { gamephysics, openPage, out, root } from "./browser.mjs";

const catalog = JSON.parse(readFileSync(path.join(root, "srs/catalog.json"), "utf8"));
const modelKeys = ["theoretical_models", "general_definitions", "data_definitions", "instance_models"];
const otherKeys = ["goals", "assumptions", "functional_requirements", "nonfunctional_requirements",
  "likely_changes", "unlikely_changes"];
const modelIds = modelKeys.flatMap((k) => catalog[k].map((m) => m.id));
const allIds = [...modelIds, ...otherKeys.flatMap((k) => catalog[k].map((m) => m.id))];

test("the audit page shows every SRS id, each model's equation typeset by KaTeX", async () => {
  const dir = path.join(out, "browser_audit");
  gamephysics("audit", "--root", root, "--out", dir);
  const { page, requests, errors, close } = await openPage(path.join(dir, "audit.html"));
  try {
    const sections = await page.$$eval(".srs-item", (els) => els.map((e) => ({
      id: e.dataset.id,
      equations: e.querySelectorAll(".equation .katex-display .katex").length,
      heading: e.querySelector("h3").textContent,
    })));
    const shown = new Map(sections.map((s) => [s.id, s]));
    for (const id of allIds) assert.ok(shown.has(id), `${id} has a section`);
    assert.equal(sections.length, allIds.length);
    let rendered = 0;
    for (const id of modelIds) {
      assert.equal(shown.get(id).equations, 1, `${id}: its equation is typeset`);
      ++rendered;
    }
    assert.equal(await page.locator(".katex-error").count(), 0, "KaTeX reported no error");
    assert.equal(await page.locator("#no-katex").count(), 0);
    // Written by `audit` alone, beside no report: no link to one.
    assert.equal(await page.locator('a[href="index.html"]').count(), 0);
    const symbols = await page.locator(".symbols .katex").count();
    assert.ok(symbols > 0);
    const matrices = await page.$$eval("table.matrix", (ts) => ts.map((t) => t.id));
    assert.deepEqual(matrices.sort(), ["matrix-assumptions_vs_assumptions", "matrix-assumptions_vs_items",
      "matrix-items_vs_items", "matrix-requirements_vs_items"]);
    await page.screenshot({ path: path.join(out, "audit_top.png") });
    await page.locator('[data-id="DD:kEnergy"]').screenshot({ path: path.join(out, "audit_dd_kenergy.png") });
    console.log(`audit: ${sections.length} of ${allIds.length} SRS ids shown, ${rendered} of ` +
      `${modelIds.length} model equations and ${symbols} symbols typeset, no KaTeX error`);
    assert.deepEqual(requests, [], "the page fetches nothing");
    assert.deepEqual(errors, [], "no script error");
  } finally {
    await close();
  }
});
