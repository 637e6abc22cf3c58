// What the browser tests share: the paths ctest gives them, the programs they run and Debian's
// chromium driven by playwright-core (tools/web), started as this closed network needs.
import { execFileSync } from "node:child_process";
import { mkdtempSync, rmSync } from "node:fs";
import { createRequire } from "node:module";
import { tmpdir } from "node:os";
import path from "node:path";

export const root = process.env.GP_ROOT;   // the repository
export const bin = process.env.GP_BIN;     // build/bin/gamephysics
export const out = process.env.GP_OUT;     // where pages, CSV and screenshots go (the build tree)
if (!root || !bin || !out) throw new Error("set GP_ROOT, GP_BIN and GP_OUT (tests/CMakeLists.txt does)");

const { chromium } = createRequire(path.join(root, "tools/web/package.json"))("playwright-core");

/// Runs build/bin/gamephysics with `args`; throws with its output when it fails.
export function gamephysics(...args) {
  return execFileSync(bin, args, { cwd: root, encoding: "utf8" });
}

/// A page of a fresh headless chromium (new user-data-dir), with every request that leaves
/// the file (anything but file: and data: URLs) and every script error recorded; `hash` is
/// appended to the file's URL (e.g. "#t=1.4").
export async function openPage(file, hash = "") {
  const profile = mkdtempSync(path.join(tmpdir(), "gp-chromium-"));
  const context = await chromium.launchPersistentContext(profile, {
    executablePath: "/usr/bin/chromium",
    headless: true,
    viewport: { width: 1400, height: 1000 },
    deviceScaleFactor: 1,
    args: ["--no-sandbox", "--disable-gpu", "--disable-quic", "--disable-background-networking",
      "--disable-component-update", "--disable-sync", "--no-first-run"],
  });
  const page = context.pages()[0] ?? (await context.newPage());
  const requests = [], errors = [];
  page.on("request", (r) => { if (!/^(file|data):/.test(r.url())) requests.push(r.url()); });
  page.on("pageerror", (e) => errors.push(String(e)));
  page.on("console", (m) => { if (m.type() === "error") errors.push(m.text()); });
  await page.goto("file://" + path.resolve(file) + hash);
  const close = async () => { await context.close(); rmSync(profile, { recursive: true, force: true }); };
  return { page, requests, errors, close };
}
