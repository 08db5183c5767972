// Browser test of `highlift report`: writes the report of a project, loads it in headless
// Chromium (Debian's chromium package) from a file:// URL and checks it, talking the DevTools
// protocol over a pipe (--remote-debugging-pipe: no extra npm package, no WebSocket).
//
//   node browser_test.mjs --highlift build/cli/highlift --project examples/a380_class_flaps.json \
//        --out build/tests/report/browser [--campaign DIR] [--optimize RESULT.json]
//
// With --campaign DIR (a `highlift campaign` result of the project) the report is written with
// that campaign (and without simulations of its own) and the envelope plot and tables are checked.
// With --optimize RESULT.json (`highlift optimize --json` of the project) the report is written with
// the Synthesis section (no simulations of its own): its status, design table and, for a --pareto
// result, the front's plot (a mark per point), its table and the design shown when the cursor is
// on a point.
//
// Fails on: a console error or uncaught exception; any network request (the file must hold
// everything); an external address in the file; a plot whose canvas is missing or blank or that
// drew fewer series or points than its data holds; an architecture drawing without a mark per
// component; a summary that differs from `highlift check --json`; a file over 5 MB. Saves
// screenshots (the top of the page, each section, the first and last scenario) in the output folder. Exit 77 (ctest: skipped)
// when no Chromium is installed.
import { spawn, spawnSync } from "node:child_process";
import fs from "node:fs";
import os from "node:os";
import path from "node:path";
import { pathToFileURL } from "node:url";

const args = Object.fromEntries(
  process.argv.slice(2).reduce((pairs, a, i, all) => (a.startsWith("--") ? [...pairs, [a.slice(2), all[i + 1]]] : pairs), []));
for (const required of ["highlift", "project", "out"])
  if (!args[required]) { console.error(`usage: node browser_test.mjs --highlift BIN --project FILE --out DIR (missing --${required})`); process.exit(2); }

const failures = [];
const check = (ok, what) => { if (!ok) failures.push(what); return ok; };
const log = (...a) => console.log("[browser-test]", ...a);

// ------------------------------------------------------------------------------------- Chromium
const candidates = [process.env.CHROMIUM, "/usr/bin/chromium", "/usr/bin/chromium-browser"].filter(Boolean);
const chromium = candidates.find((c) => fs.existsSync(c));
if (!chromium) {
  console.log("SKIPPED: no Chromium found (" + candidates.join(", ") + "); install Debian's chromium package " +
              "(scripts/install-deps.sh does) to run the browser test");
  process.exit(77);
}

// ------------------------------------------------------------------------------------- report and check
fs.mkdirSync(args.out, { recursive: true });
// --report FILE: check a report written before (while working on the page) instead of writing one.
const html = path.resolve(args.report || path.join(args.out, "report.html"));
let t0 = Date.now();
if (!args.report) {
  const extra = args.campaign ? ["--campaign", args.campaign, "--no-transient", "--no-scenarios"] : [];
  if (args.optimize) extra.push("--optimize", args.optimize, ...(args.campaign ? [] : ["--no-transient", "--no-scenarios"]));
  const made = spawnSync(args.highlift, ["report", args.project, "--out", html, "--json", ...extra], { encoding: "utf8" });
  if (made.status !== 0 && made.status !== 1) {
    console.error("highlift report failed with exit code " + made.status + ":\n" + made.stderr);
    process.exit(1);
  }
  const doc = JSON.parse(made.stdout);
  log(`highlift report: ${((Date.now() - t0) / 1000).toFixed(1)} s wall, ${doc.bytes} bytes, timings ${JSON.stringify(doc.timings)}`);
}
const checked = spawnSync(args.highlift, ["check", args.project, "--json"], { encoding: "utf8", maxBuffer: 64 << 20 });
if (checked.status !== 0 && checked.status !== 1) {
  console.error("highlift check failed with exit code " + checked.status + ":\n" + checked.stderr);
  process.exit(1);
}
const checkDoc = JSON.parse(checked.stdout);

// ------------------------------------------------------------------------------------- the file itself
const text = fs.readFileSync(html, "utf8");
check(text.length < 5 * 1024 * 1024, `report is ${text.length} bytes, over 5 MB`);
const external = text.match(/\b(?:https?|ftp|wss?):\/\/[^\s"'<>)]*/gi) || [];
check(external.length === 0, "external addresses in the file: " + [...new Set(external)].slice(0, 5).join(", "));
check(!/<(?:link|iframe|img|embed|object)\b/i.test(text), "the file loads a resource element (<link>, <img>, ...)");
check(!/<script[^>]*\bsrc\s*=/i.test(text), "a <script src=...> in the file");
check(!/@import|url\(\s*['"]?(?!data:)[^)]/i.test(text), "a CSS @import or url() in the file");
const dataText = text.match(/<script type="application\/json" id="report-data">([\s\S]*?)<\/script>/);
check(dataText, "no data island #report-data in the file");
const data = JSON.parse(dataText[1]);

// ------------------------------------------------------------------------------------- DevTools over a pipe
const profile = fs.mkdtempSync(path.join(os.tmpdir(), "highlift-chromium-"));
const browser = spawn(chromium, [
  "--headless", "--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run", "--disable-background-networking",
  "--disable-component-update", "--disable-sync", "--disable-extensions", "--hide-scrollbars", "--mute-audio",
  `--user-data-dir=${profile}`, "--remote-debugging-pipe", "--window-size=1400,1000", "about:blank",
], { stdio: ["ignore", "ignore", "pipe", "pipe", "pipe"] });
let browserLog = "";
browser.stderr.on("data", (d) => { browserLog += d; });
const toBrowser = browser.stdio[3], fromBrowser = browser.stdio[4];
let nextId = 1, buffer = Buffer.alloc(0);
const pending = new Map(), listeners = [];
fromBrowser.on("data", (chunk) => {
  buffer = Buffer.concat([buffer, chunk]);
  for (let end = buffer.indexOf(0); end >= 0; end = buffer.indexOf(0)) {
    const message = JSON.parse(buffer.subarray(0, end).toString("utf8"));
    buffer = buffer.subarray(end + 1);
    if (message.id && pending.has(message.id)) {
      const { resolve, reject, method } = pending.get(message.id);
      pending.delete(message.id);
      if (message.error) reject(new Error(method + ": " + message.error.message)); else resolve(message.result);
    } else if (message.method) {
      for (const l of listeners) l(message);
    }
  }
});
function send(method, params = {}, sessionId) {
  const id = nextId++;
  toBrowser.write(JSON.stringify({ id, method, params, ...(sessionId ? { sessionId } : {}) }) + "\0");
  return new Promise((resolve, reject) => pending.set(id, { resolve, reject, method }));
}
const sleep = (ms) => new Promise((r) => setTimeout(r, ms));
async function finish(code) {
  // Close the browser, wait for it to exit, then remove its profile.
  const exited = new Promise((resolve) => browser.once("exit", resolve));
  try { toBrowser.write(JSON.stringify({ id: nextId++, method: "Browser.close" }) + "\0"); } catch { browser.kill(); }
  await Promise.race([exited, sleep(5000).then(() => browser.kill("SIGKILL"))]);
  try { fs.rmSync(profile, { recursive: true, force: true }); } catch (e) { console.error("could not remove " + profile + ": " + e.message); }
  process.exit(code);
}
const watchdog = setTimeout(() => {
  console.error("browser test timed out after 55 s\n" + browserLog.slice(-2000));
  finish(1);
}, 55000);
watchdog.unref();

try {
  const consoleErrors = [], requests = [];
  const fileUrl = pathToFileURL(html).href;
  listeners.push((m) => {
    if (m.method === "Runtime.consoleAPICalled" && (m.params.type === "error" || m.params.type === "assert"))
      consoleErrors.push("console." + m.params.type + ": " + m.params.args.map((a) => a.value ?? a.description).join(" "));
    if (m.method === "Runtime.exceptionThrown")
      consoleErrors.push("exception: " + (m.params.exceptionDetails.exception?.description || m.params.exceptionDetails.text));
    if (m.method === "Log.entryAdded" && m.params.entry.level === "error")
      consoleErrors.push("log: " + m.params.entry.text + (m.params.entry.url ? " (" + m.params.entry.url + ")" : ""));
    if (m.method === "Network.requestWillBeSent") requests.push(m.params.request.url);
  });
  let loaded = false;
  listeners.push((m) => { if (m.method === "Page.loadEventFired") loaded = true; });

  const { targetId } = await send("Target.createTarget", { url: "about:blank" });
  const { sessionId } = await send("Target.attachToTarget", { targetId, flatten: true });
  const page = (method, params) => send(method, params, sessionId);
  for (const domain of ["Runtime", "Log", "Network", "Page"]) await page(domain + ".enable");
  await page("Emulation.setDeviceMetricsOverride", { width: 1400, height: 1000, deviceScaleFactor: 1, mobile: false });
  t0 = Date.now();
  await page("Page.navigate", { url: fileUrl });
  const evaluate = async (expression) => {
    const r = await page("Runtime.evaluate", { expression, returnByValue: true, awaitPromise: true });
    if (r.exceptionDetails) throw new Error("evaluating in the page: " + (r.exceptionDetails.exception?.description || r.exceptionDetails.text));
    return r.result.value;
  };
  for (let waited = 0; !(loaded && (await evaluate("!!(window.highliftReport && window.highliftReport.ready)"))); waited += 100) {
    if (waited > 30000) throw new Error("the page did not finish rendering within 30 s");
    await sleep(100);
  }
  await sleep(300);  // let uPlot's deferred first draw happen
  log(`page loaded and rendered in ${((Date.now() - t0) / 1000).toFixed(2)} s`);

  const seen = await evaluate(`(() => {
    const s = window.highliftReport;
    const inked = (canvas) => {
      if (!canvas || !canvas.width || !canvas.height) return 0;
      const px = canvas.getContext("2d").getImageData(0, 0, canvas.width, canvas.height).data;
      let n = 0;
      for (let i = 3; i < px.length; i += 4) if (px[i] > 0) n++;
      return n;
    };
    const list = (sel) => [...document.querySelectorAll(sel)].map((li) => li.dataset.requirement);
    const anchors = [...document.querySelectorAll('a[href^="#"]')].map((a) => a.getAttribute("href").slice(1));
    return {
      errors: s.errors,
      plots: s.plots.map((p) => ({ id: p.id, series: p.series, points: p.points, drawnSeries: p.drawnSeries, bars: p.bars,
                                   canvas: p.canvas ? { width: p.canvas.width, height: p.canvas.height, inked: inked(p.canvas) } : null })),
      drawing: s.drawing,
      svgComponents: document.querySelectorAll("#architecture-svg a.component").length,
      svgEdges: document.querySelectorAll("#architecture-svg line.edge").length,
      componentTables: document.querySelectorAll("details.component").length,
      brokenAnchors: anchors.filter((id) => id && !document.getElementById(decodeURIComponent(id))),
      verdict: document.getElementById("verdict").textContent,
      status: document.getElementById("verdict").dataset.status,
      domains: document.getElementById("domains-statement").textContent,
      nominal: document.getElementById("nominal-statement").textContent,
      violated: list("ul.violated-list.domains li"),
      nominalViolated: list("ul.violated-list.nominal li"),
      explanation: document.getElementById("explanation").textContent,
      marginsRows: document.querySelectorAll("#worst-margins tbody tr").length,
      peakRows: document.querySelectorAll("#peaks-table tbody tr").length,
      envelopeRows: document.querySelectorAll("#campaign-envelope-table tbody tr").length,
      campaignCaseRows: document.querySelectorAll("#campaign-cases-table tbody tr").length,
      synthesisStatus: document.getElementById("synthesis-status")?.dataset.status ?? null,
      synthesisDesignRows: document.querySelectorAll("#synthesis-design tbody tr").length,
      paretoRows: document.querySelectorAll("#synthesis-pareto-table tbody tr").length,
    };
  })()`);

  // Console and network
  check(consoleErrors.length === 0, "console errors: " + consoleErrors.slice(0, 5).join(" | "));
  check(seen.errors.length === 0, "rendering errors: " + seen.errors.join(" | "));
  const foreign = requests.filter((u) => u !== fileUrl && !u.startsWith("data:"));
  check(foreign.length === 0, "the page requested: " + foreign.slice(0, 5).join(", "));

  // Summary = `highlift check --json`
  const met = checkDoc.all_requirements_met;
  const nominalViolated = checkDoc.nominal_design?.violated_requirements ?? [];
  const expectedStatus = met === null ? "undecided" : !met ? "infeasible" : nominalViolated.length || checkDoc.nominal_design?.all_requirements_met === false
    ? "feasible_domains_nominal_violates" : "feasible";
  check(seen.status === expectedStatus, `summary status '${seen.status}', check --json says '${expectedStatus}'`);
  check(JSON.stringify(seen.violated) === JSON.stringify(checkDoc.violated_requirements ?? []),
        `summary lists violated ${JSON.stringify(seen.violated)}, check --json ${JSON.stringify(checkDoc.violated_requirements ?? [])}`);
  check(JSON.stringify(seen.nominalViolated) === JSON.stringify(nominalViolated),
        `summary lists nominal violations ${JSON.stringify(seen.nominalViolated)}, check --json ${JSON.stringify(nominalViolated)}`);
  for (const name of [...(checkDoc.violated_requirements ?? []), ...nominalViolated])
    check(seen.verdict.includes(name), `the verdict line '${seen.verdict}' does not name ${name}`);
  const explanation = checkDoc.explanation ?? checkDoc.nominal_design?.explanation ?? "";
  check(seen.explanation === explanation, "the explanation on the page differs from check --json's");
  check(seen.domains.startsWith("Parameter domains:"), "the domain statement does not say it concerns the domains: " + seen.domains);
  if (checkDoc.nominal_design) check(seen.nominal.startsWith("Nominal design"), "the nominal statement does not say it concerns the nominal design: " + seen.nominal);
  check(JSON.stringify(data.check.parameters.map((p) => [p.name, p.final])) === JSON.stringify(checkDoc.parameters.map((p) => [p.name, p.final])),
        "the report's parameter domains differ from check --json's");
  check(seen.marginsRows > 0, "no worst margins in the summary");

  // Architecture: a mark per component, a line per connection, a table per component
  const placed = data.components.filter((c) => c.x != null).length;
  check(placed === data.components.length, `${data.components.length - placed} components without a span position`);
  check(seen.svgComponents === placed && seen.drawing.components === placed, `architecture drew ${seen.svgComponents} components of ${placed}`);
  const drawableEdges = data.edges.filter(([a, b]) => data.components[a].x != null && data.components[b].x != null).length;
  check(seen.svgEdges === drawableEdges, `architecture drew ${seen.svgEdges} connections of ${drawableEdges}`);
  check(seen.componentTables === data.components.length, `${seen.componentTables} component tables of ${data.components.length}`);
  check(seen.brokenAnchors.length === 0, "links to missing targets: " + seen.brokenAnchors.slice(0, 5).join(", "));

  // Plots: every expected plot present, its canvas inked, every series drawn with all its points
  const expected = new Map();  // id -> series count from the data
  for (const lc of data.sizing.load_cases) if (lc.components.some((t) => t.type === "torque_shaft")) expected.set("sizing-" + lc.name, 4);
  expected.set("modes-full", Math.min(3, data.modes.models[0].clamped_shapes.length));
  expected.set("modes-first", data.modes.models.length);
  expected.set("peaks-plot", 3);
  if (data.campaign) expected.set("campaign-envelope", 2);
  const paretoMarks = data.synthesis && data.synthesis.pareto
    ? data.synthesis.pareto.front.filter((f) => f.objective != null && f.second != null).length : 0;
  if (paretoMarks) expected.set("synthesis-pareto", 2);  // a front without any design gets a sentence, no plot
  check(!args.optimize || data.synthesis, "--optimize given, and the report holds no synthesis");
  check(!args.campaign || data.campaign, "--campaign given, and the report holds no campaign");
  for (const s of data.scenarios)
    for (const g of ["speed", "torque", "state"]) {
      const n = s.signals.filter((x) => x.group === g).length;
      if (n) expected.set(`scenario-${s.name}-${g}`, n);
    }
  const byId = new Map(seen.plots.map((p) => [p.id, p]));
  for (const [id, series] of expected) {
    const p = byId.get(id);
    if (!check(p, `plot ${id} missing`)) continue;
    check(p.canvas && p.canvas.width > 0 && p.canvas.height > 0, `plot ${id}: no canvas`);
    check(p.canvas && p.canvas.inked > 1000, `plot ${id}: canvas blank (${p.canvas?.inked} inked pixels)`);
    check(p.series === series, `plot ${id}: ${p.series} series, the data has ${series}`);
    for (let si = 1; si <= series; si++)
      check(p.drawnSeries[si] === p.points[si - 1], `plot ${id}: series ${si} drew ${p.drawnSeries[si]} points of ${p.points[si - 1]}`);
  }
  for (const s of data.scenarios)
    for (const g of s.signals) {
      const p = byId.get(`scenario-${s.name}-${g.group}`);
      const k = s.signals.filter((x) => x.group === g.group).indexOf(g);
      if (p) check(p.points[k] === g.values.filter((v) => v != null).length, `plot of ${s.name} ${g.name}: ${p.points[k]} points, data ${g.values.length}`);
    }
  const peaks = byId.get("peaks-plot");
  if (peaks) {
    const singles = data.peak_cases.filter((c) => c.single_dof.nominal != null).length;
    const transients = data.peak_cases.filter((c) => c.transient && c.transient.ok && c.transient.value != null).length;
    check((peaks.bars[1] || 0) === singles, `peak plot drew ${peaks.bars[1]} single-DOF bars of ${singles}`);
    check((peaks.bars[2] || 0) === transients, `peak plot drew ${peaks.bars[2]} transient bars of ${transients}`);
  }
  if (data.campaign) {
    const envelope = byId.get("campaign-envelope");
    if (envelope) check(envelope.bars[1] === data.campaign.envelope.length,
                        `envelope plot drew ${envelope.bars[1]} bars of ${data.campaign.envelope.length} components`);
    check(seen.envelopeRows === data.campaign.envelope.length, `envelope table has ${seen.envelopeRows} rows of ${data.campaign.envelope.length}`);
    check(seen.campaignCaseRows === data.campaign.case_peaks.length,
          `campaign case table has ${seen.campaignCaseRows} rows of ${data.campaign.case_peaks.length}`);
    check(data.campaign.envelope.length > 0, "the campaign's envelope is empty");
  }
  if (data.synthesis) {
    const s = data.synthesis;
    check(seen.synthesisStatus === s.status, `synthesis status on the page '${seen.synthesisStatus}', data '${s.status}'`);
    if (s.found) check(seen.synthesisDesignRows === s.design.length, `synthesis design table has ${seen.synthesisDesignRows} rows of ${s.design.length}`);
  }
  if (args.optimize && data.synthesis && data.synthesis.pareto) {
    const front = data.synthesis.pareto.front;
    const marks = paretoMarks;
    check(marks >= 2, `the Pareto front has ${marks} points with both objectives`);
    check(seen.paretoRows === front.length, `Pareto table has ${seen.paretoRows} rows of ${front.length} points`);
    // Each point's design is reachable from the plot: put the cursor on every mark, read the readout.
    const hovered = await evaluate(`(() => {
      const u = window.highliftReport.plots.find((p) => p.id === "synthesis-pareto").uplot;
      const out = [];
      for (let i = 0; i < u.data[0].length; i++) {
        if (u.data[1][i] == null) continue;
        u.setCursor({ left: u.valToPos(u.data[0][i], "x"), top: u.valToPos(u.data[1][i], "y") });
        out.push({ text: document.getElementById("synthesis-pareto-readout").textContent,
                   highlighted: document.querySelectorAll("#synthesis-pareto-table tr.highlight").length });
      }
      return out;
    })()`);
    check(hovered.length === marks, `the cursor reached ${hovered.length} marks of ${marks}`);
    const names = data.synthesis.design.map((d) => d.name);
    for (const [k, h] of hovered.entries()) {
      check(/^point \d+: /.test(h.text) && names.every((n) => h.text.includes(n + " = ")),
            `cursor on Pareto mark ${k + 1}: the readout '${h.text}' does not show the point's design`);
      check(h.highlighted === 1, `cursor on Pareto mark ${k + 1}: ${h.highlighted} table rows highlighted`);
    }
  }
  check(seen.peakRows === data.peak_cases.length, `peak table has ${seen.peakRows} rows of ${data.peak_cases.length} cases`);
  check(seen.plots.length === expected.size, `${seen.plots.length} plots on the page, ${expected.size} expected`);

  // Screenshots
  const top = await page("Page.captureScreenshot", { format: "png" });
  fs.writeFileSync(path.join(args.out, "report_top.png"), Buffer.from(top.data, "base64"));
  // One per section (the first 4000 px of each) and the first and last scenario, to look at.
  const boxes = await evaluate(`[...document.querySelectorAll("main > section, div.scenario:first-child, div.scenario:last-child")].map((s) => {
    const r = s.getBoundingClientRect();
    return { id: s.id, x: r.left + window.scrollX, y: r.top + window.scrollY, width: r.width, height: r.height };
  })`);
  for (const b of boxes) {
    const shot = await page("Page.captureScreenshot", {
      format: "png", captureBeyondViewport: true, clip: { x: b.x, y: b.y, width: b.width, height: Math.min(b.height, 4000), scale: 1 } });
    fs.writeFileSync(path.join(args.out, `${b.id}.png`), Buffer.from(shot.data, "base64"));
  }
  log(`screenshots in ${args.out}: report_top.png, ` + boxes.map((b) => `${b.id}.png`).join(", "));
  log(`${seen.plots.length} plots, ${seen.svgComponents} components drawn, verdict: ${seen.verdict}`);
} catch (e) {
  failures.push(String(e && e.stack || e));
}
clearTimeout(watchdog);
if (failures.length) {
  console.error("FAILED:\n  " + failures.join("\n  "));
  await finish(1);
}
log("passed");
await finish(0);
