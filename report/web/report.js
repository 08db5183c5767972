// highlift design report: renders the data island #report-data with uPlot (plots) and inline SVG
// (the architecture). Every plot registers itself in window.highliftReport.plots with the series
// and points it was given and the marks uPlot drew, for the browser test (tests/report).
(function () {
  "use strict";
  const state = { ready: false, plots: [], errors: [], drawing: null };
  window.highliftReport = state;
  window.addEventListener("error", (e) => state.errors.push(String(e.message)));

  const data = JSON.parse(document.getElementById("report-data").textContent);
  const COLORS = ["#0b5cad", "#d1462f", "#1a7f37", "#9a6700", "#6f42c1", "#00838f", "#c2185b", "#5d4037", "#455a64"];

  // ---------------------------------------------------------------------------------------- helpers
  function el(tag, attrs, ...children) {
    const e = document.createElement(tag);
    for (const [k, v] of Object.entries(attrs || {})) {
      if (k === "class") e.className = v;
      else if (k === "text") e.textContent = v;
      else e.setAttribute(k, v);
    }
    for (const c of children) if (c != null) e.append(c);
    return e;
  }
  function fmt(v, digits) {
    if (v == null) return "\u2013";
    if (typeof v === "string") return v;
    if (!isFinite(v)) return v > 0 ? "inf" : "-inf";
    if (v === 0) return "0";
    const a = Math.abs(v);
    if (a >= 1e6 || a < 1e-3) return v.toExponential((digits || 4) - 1);
    return String(Number(v.toPrecision(digits || 4)));
  }
  function percent(m) { return m == null ? "\u2013" : (m * 100).toFixed(1) + " %"; }
  function table(headers, rows, numeric) {
    const t = el("table");
    t.append(el("thead", {}, el("tr", {}, ...headers.map((h) => el("th", { text: h })))));
    const body = el("tbody");
    for (const r of rows) {
      const tr = el("tr");
      r.forEach((cell, i) => {
        const td = el("td", { class: numeric && numeric.includes(i) ? "num" : "" });
        if (cell instanceof Node) td.append(cell); else td.textContent = cell == null ? "\u2013" : String(cell);
        tr.append(td);
      });
      body.append(tr);
    }
    t.append(body);
    return t;
  }
  function escapeXml(s) {
    return String(s).replace(/[&<>"']/g, (c) => ({ "&": "&amp;", "<": "&lt;", ">": "&gt;", '"': "&quot;", "'": "&#39;" }[c]));
  }
  const plotWidth = () => Math.max(600, Math.min(1400, document.getElementById("summary").clientWidth - 10));

  // A uPlot chart that records what it drew. `series` are uPlot series options (without the x
  // series); `columns` the data, x first.
  function plot(container, id, title, columns, series, options) {
    const box = el("div", { class: "plot", id: id });
    box.append(el("div", { class: "plot-title", text: title }));
    container.append(box);
    const record = { id: id, title: title, series: series.length, points: [], drawnSeries: {}, bars: {} };
    for (let s = 1; s < columns.length; s++) record.points.push(columns[s].filter((v) => v != null).length);
    const opts = Object.assign({
      width: plotWidth(),
      height: 300,
      series: [{ label: "x" }].concat(series),
      hooks: {},
    }, options || {});
    opts.hooks.drawClear = [(u) => { record.drawnSeries = {}; record.bars = {}; }];
    opts.hooks.drawSeries = [(u, si) => {
      // Points of the series inside the visible x range.
      const xs = u.data[0], ys = u.data[si], min = u.scales.x.min, max = u.scales.x.max;
      let n = 0;
      for (let i = 0; i < xs.length; i++) if (ys[i] != null && xs[i] >= min && xs[i] <= max) n++;
      record.drawnSeries[si] = n;
    }];
    const u = new uPlot(opts, columns, box);
    record.uplot = u;
    record.canvas = box.querySelector("canvas");
    state.plots.push(record);
    return u;
  }
  // Bars that count themselves as they are drawn.
  function bars(recordId, align, size) {
    return uPlot.paths.bars({ size: [size, 40], align: align,
      each: (u, si) => { const r = state.plots.find((p) => p.id === recordId); if (r) r.bars[si] = (r.bars[si] || 0) + 1; } });
  }

  // ---------------------------------------------------------------------------------------- summary
  function renderSummary() {
    const v = data.verdict, check = data.check;
    const verdict = document.getElementById("verdict");
    verdict.textContent = v.headline;
    verdict.classList.add(v.status);
    verdict.dataset.status = v.status;
    document.getElementById("domains-statement").textContent = v.domains;
    document.getElementById("nominal-statement").textContent = v.nominal;
    const reqs = new Map(data.requirements.map((r) => [r.id, r]));
    const violatedBox = document.getElementById("violated");
    const listOf = (names, heading, cls) => {
      if (!names || !names.length) return;
      violatedBox.append(el("h3", { text: heading }));
      const ul = el("ul", { class: "violated-list " + cls });
      for (const n of names) {
        const r = reqs.get(n);
        ul.append(el("li", { "data-requirement": n }, el("strong", { text: n }), r ? ": " : "",
          r ? el("code", { text: r.expression }) : null, r && r.description ? " \u2014 " + r.description : ""));
      }
      violatedBox.append(ul);
    };
    listOf(check.violated_requirements, "Requirements no values within the domains can meet", "domains");
    if (check.nominal_design) listOf(check.nominal_design.violated_requirements, "Requirements the nominal design violates", "nominal");
    const explanation = check.explanation || (check.nominal_design && check.nominal_design.explanation) || "";
    document.getElementById("explanation").textContent = explanation;
    if (!explanation) document.getElementById("explanation-box").hidden = true;
    // The ten smallest, components with the same margin of the same kind in one row.
    const groups = [];
    for (const m of data.margins) {
      const kind = m.what.split(",")[0];
      const key = [fmt(m.margin, 3), fmt(m.load), fmt(m.allowable), m.allowable_name, kind].join("|");
      const g = groups.find((x) => x.key === key);
      if (g) { g.members.push(m); continue; }
      if (groups.length === 10) break;
      groups.push({ key: key, members: [m] });
    }
    document.getElementById("worst-margins").append(table(
      ["margin", "component", "load [N*m]", "allowable [N*m]", "allowable", "from"],
      groups.map((g) => {
        const m = g.members[0];
        const cell = el("span", { class: m.margin != null && m.margin < 0 ? "bad" : "", text: percent(m.margin) });
        const who = el("span");
        g.members.forEach((x, i) => { if (i) who.append(", "); who.append(componentLink(x.component)); });
        const names = [...new Set(g.members.map((x) => x.what.split(", ")[1] || "").filter(Boolean))];
        const cases = m.what.split(",")[0] + (names.length ? " (" + names.join(", ") + ")" : "");
        return [cell, who, fmt(m.load), fmt(m.allowable), m.allowable_name, cases];
      }), [0, 2, 3]));
  }

  const componentIds = new Set(data.components.map((c) => c.id));
  function componentLink(id) {
    if (!id) return "\u2013";
    if (!componentIds.has(id)) return id;  // an element of a component (e.g. a shaft segment): no table to link to
    const a = el("a", { href: "#c-" + id, text: id });
    return a;
  }

  // ---------------------------------------------------------------------------------------- synthesis
  // The result of `highlift optimize --json` (`highlift report --optimize FILE`): status, the best
  // design's worst-case objective beside the certified lower bound, the design, what limits it, the
  // mass by component and, for a --pareto run, the front (plot and table, each point's design).
  function renderSynthesis() {
    const box = document.getElementById("synthesis-body");
    const s = data.synthesis;
    if (!s) {
      box.append(el("p", { class: "hint", text: "No optimisation result in this report: run `highlift optimize PROJECT --json > result.json` " +
        "(with --pareto OBJ1,OBJ2 for a front of two objectives) and `highlift report PROJECT --optimize result.json` to show it here." }));
      return;
    }
    const withUnit = (v, unit) => fmt(v) + (unit && v != null ? " " + unit : "");
    // The relative gap as optimize prints it: small ones as numbers (0.0 % would hide them).
    const gapText = (g) => (g == null ? "\u2013" : g >= 1e-3 ? (g * 100).toFixed(2) + " %" : fmt(g, 3));
    const bracket = (unit) => (unit ? " [" + unit + "]" : "");
    const u1 = s.objective_unit;
    const cls = !s.found ? "infeasible" : s.status === "optimal" ? "feasible" : "feasible_domains_nominal_violates";
    const headline = s.found
      ? s.status_words + ". " + s.objective + " " + withUnit(s.best, u1) + " (worst case), certified \u2265 " + withUnit(s.lower_bound, u1) +
        ", gap " + gapText(s.gap)
      : s.status_words + (s.message ? ". " + s.message : "");
    const line = el("p", { class: "verdict " + cls, id: "synthesis-status", text: headline });
    line.dataset.status = s.status;
    box.append(line);
    box.append(el("p", { class: "hint", text: s.relation === "design"
      ? "From `highlift optimize " + s.project_file + "` (" + s.file + "); this project is the design it wrote (--write), so the sections below analyse the optimised design."
      : "From `highlift optimize` on this project (" + s.file + "). The sections below analyse the project as given, not the optimised design: " +
        "write the design with `highlift optimize ... --write best.json` and run `highlift report best.json --optimize " + s.file + "` to see its loads." }));
    if (s.found) {
      box.append(el("div", { id: "synthesis-objective" }, table(["objective: " + s.objective, "value" + bracket(u1), "what it is"], [
        ["best design, worst case", fmt(s.best), "the design's objective over every value of the remaining uncertain parameters (an upper bound for it)"],
        ["certified lower bound", fmt(s.lower_bound), "proved: no design within the domains that meets every constraint for every value of the uncertain parameters has less"],
        ["relative gap", gapText(s.gap), "(worst case \u2212 bound) / |worst case|: how far the design can be from the best possible one at most"],
      ], [1])));
      box.append(el("h3", { text: "Design" }));
      box.append(el("div", { id: "synthesis-design" }, table(["design variable", "unit", "optimised", "domain", "nominal", "at bound"],
        s.design.map((d) => [el("span", {}, componentLink(d.component), d.name.slice(d.component.length)), d.unit, fmt(d.value),
          "[" + fmt(d.lower) + ", " + fmt(d.upper) + "]", fmt(d.nominal), d.at_bound ? el("strong", { text: d.at_bound }) : ""]), [2, 4])));
      const parts = Object.entries(s.parts || {});
      if (parts.length) box.append(el("p", { text: "Parts chosen: " + parts.map(([c, p]) => c + ": " + p).join(", ") }));
      const tubes = Object.entries((s.tube_sizes && s.tube_sizes.shafts) || {});
      if (tubes.length) box.append(el("p", { text: "Tube sizes (" + s.tube_sizes.table + "): " + tubes.map(([c, z]) => c + ": " + z).join(", ") }));
      box.append(el("h3", { text: "What limits the design" }));
      box.append(el("p", { class: "hint", text: "The constraints that no longer hold for certain one step of 1e-4 of the domains towards a smaller " +
        s.objective + ", and the design variables at a bound of their domain." }));
      const ul = el("ul", { class: "violated-list", id: "synthesis-active" });
      for (const a of s.active_constraints)
        ul.append(el("li", {}, el("strong", { text: a.label }), ": " + a.description, a.text ? " \u2014 " : "", a.text ? el("code", { text: a.text }) : null));
      if (!s.active_constraints.length) ul.append(el("li", { text: "nothing found at that step" }));
      box.append(ul);
      if (s.mass_terms.length) {
        box.append(el("h3", { text: "Mass by component" }));
        box.append(el("p", { class: "hint", text: "At the best design, over the remaining domains; the law is where each mass comes from (its provenance)." }));
        box.append(el("div", { id: "synthesis-mass" }, table(["component", "min [kg]", "max [kg]", "law"],
          s.mass_terms.map((m) => [componentLink(m.component), fmt(m.min), fmt(m.max), m.law]), [1, 2])));
      }
    }
    if (s.explanation) {
      box.append(el("h3", { text: "Why no design" }));
      box.append(el("pre", { id: "synthesis-explanation", text: s.explanation }));
    }
    if (!s.found && s.rejections.length)
      box.append(el("p", { text: "Candidate designs were rejected by (first failing check): " + s.rejections.map((r) => r.candidates + " \u00d7 " + r.check).join(", ") }));
    const c = s.counters || {};
    if (c.boxes != null)
      box.append(el("p", { class: "hint", text: c.boxes + " boxes (" + c.pruned + " pruned by the bound, " + c.infeasible_boxes + " infeasible), " + c.candidates +
        " candidate designs (" + c.reduced_model_checks + " through size and peak), " + c.improvements + " improvements, " + fmt(c.seconds, 3) + " s." }));
    if (s.pareto) renderPareto(box, s);
  }

  function renderPareto(box, s) {
    const p = s.pareto, [o1, o2] = p.objectives, [u1, u2] = p.units;
    const bracket = (unit) => (unit ? " [" + unit + "]" : "");
    box.append(el("h3", { text: "Pareto front: " + o1 + " against " + o2 }));
    box.append(el("p", { class: "hint", text: "Each point: the design of least " + o1 + " under " + o2 + " \u2264 \u03b5, at its " + o2 +
      " (both values the worst case over the remaining uncertain parameters), joined by a line; small open circles: the certified lower bound of " + o1 +
      " under that \u03b5, at \u03b5 (inside the point\u2019s mark when the gap is closed). Point at a mark for its design, or see the table." }));
    const front = p.front.map((f, i) => Object.assign({ index: i + 1 }, f));
    if (!front.some((f) => f.objective != null && f.second != null)) {
      box.append(el("p", { class: "bad", text: "No point of the front has a design (" + (front.length ? front.map((f) => f.status).join(", ") : "no point") +
        "): nothing to plot." }));
      return;
    }
    const xs = [...new Set([...front.filter((f) => f.objective != null && f.second != null).map((f) => f.second),
                            ...front.filter((f) => f.lower_bound != null).map((f) => f.epsilon)])].sort((a, b) => a - b);
    const at = new Map(xs.map((x, i) => [x, i]));
    const y1 = xs.map(() => null), y2 = xs.map(() => null), pointAt = xs.map(() => null);
    // The cursor on either mark of a point (its design, or its bound at epsilon) shows that point;
    // where two points share an x, the design's mark wins.
    for (const f of front) if (f.lower_bound != null) { y2[at.get(f.epsilon)] = f.lower_bound; pointAt[at.get(f.epsilon)] = f; }
    for (const f of front) if (f.objective != null && f.second != null) { y1[at.get(f.second)] = f.objective; pointAt[at.get(f.second)] = f; }
    const padded = (min, max) => {
      const d = max > min ? 0.06 * (max - min) : Math.max(Math.abs(max) * 0.05, 1e-9);
      return [min - d, max + d];
    };
    const readout = el("div", { id: "synthesis-pareto-readout", class: "hint", text: "Point at a mark for its design." });
    const highlight = (f) => {
      for (const tr of document.querySelectorAll("#synthesis-pareto-table tbody tr")) tr.classList.toggle("highlight", f != null && tr.id === "pareto-point-" + f.index);
      if (!f) return;
      readout.textContent = "";
      readout.append(el("a", { href: "#pareto-point-" + f.index, text: "point " + f.index }), ": " + o1 + " " + fmt(f.objective) + (u1 ? " " + u1 : "") +
        ", " + o2 + " " + fmt(f.second) + (u2 ? " " + u2 : "") + " (" + o2 + " \u2264 " + fmt(f.epsilon) + ", " + f.status + "); design: " +
        f.design.map((d) => d.name + " = " + fmt(d.value) + (d.unit ? " " + d.unit : "")).join(", "));
    };
    plot(box, "synthesis-pareto", "Pareto front: " + o1 + bracket(u1) + " against " + o2 + bracket(u2), [xs, y1, y2], [
      { label: o1 + " at the design", stroke: "#0b5cad", width: 1.5, spanGaps: true, points: { show: true, size: 13, fill: "#0b5cad", stroke: "#0b5cad" } },
      { label: "certified lower bound of " + o1 + " (at \u03b5)", stroke: "#1a7f37", width: 0, paths: () => null, points: { show: true, size: 7, width: 1.5, fill: "#fff", stroke: "#1a7f37" } },
    ], {
      height: 340,
      scales: { x: { time: false, range: (u, min, max) => padded(min, max) }, y: { range: (u, min, max) => padded(min, max) } },
      axes: [{ label: o2 + bracket(u2) }, { label: o1 + bracket(u1), size: 70 }],
      hooks: { setCursor: [(u) => { const i = u.cursor.idx; if (i != null && pointAt[i]) highlight(pointAt[i]); }] },
    });
    box.append(readout);
    const names = s.design.map((d) => d.name);
    const unitOf = new Map(s.design.map((d) => [d.name, d.unit]));
    const t = table(["#", o2 + " \u2264 \u03b5" + bracket(u2), o2 + " at the design" + bracket(u2), o1 + " at the design" + bracket(u1),
      "certified \u2265" + bracket(u1), "status", ...names.map((n) => n + bracket(unitOf.get(n)))],
      front.map((f) => {
        const byName = new Map(f.design.map((d) => [d.name, d.value]));
        return [String(f.index), fmt(f.epsilon), fmt(f.second), fmt(f.objective), fmt(f.lower_bound), f.status, ...names.map((n) => fmt(byName.get(n)))];
      }), [0, 1, 2, 3, 4, ...names.map((_, k) => 6 + k)]);
    [...t.querySelectorAll("tbody tr")].forEach((tr, i) => { tr.id = "pareto-point-" + front[i].index; });
    box.append(el("div", { id: "synthesis-pareto-table" }, t));
  }

  // ---------------------------------------------------------------------------------------- architecture
  const GLYPHS = {
    pdu: (x, y) => `<rect class="glyph" x="${x - 14}" y="${y - 14}" width="28" height="28" rx="3" fill="#0b5cad" stroke="#083d73"/>`,
    system_torque_limiter: (x, y) => `<path class="glyph" d="M${x} ${y - 9}L${x + 9} ${y}L${x} ${y + 9}L${x - 9} ${y}Z" fill="#d1462f" stroke="#7a2318"/>`,
    station_torque_limiter: (x, y) => `<path class="glyph" d="M${x} ${y - 7}L${x + 7} ${y}L${x} ${y + 7}L${x - 7} ${y}Z" fill="#f08c78" stroke="#7a2318"/>`,
    torque_shaft: null,
    steady_bearing: (x, y) => `<circle class="glyph" cx="${x}" cy="${y}" r="4" fill="#fff" stroke="#455a64"/>`,
    universal_joint: (x, y) => `<circle class="glyph" cx="${x}" cy="${y}" r="5" fill="#b0bec5" stroke="#455a64"/>`,
    angle_gearbox: (x, y) => `<rect class="glyph" x="${x - 8}" y="${y - 8}" width="16" height="16" fill="#9a6700" stroke="#5c3d00"/>`,
    branch_gearbox: (x, y) => `<rect class="glyph" x="${x - 7}" y="${y - 7}" width="14" height="14" fill="#e0b44c" stroke="#5c3d00"/>`,
    geared_rotary_actuator: (x, y) => `<circle class="glyph" cx="${x}" cy="${y}" r="8" fill="#1a7f37" stroke="#0d4a1f"/>`,
    ballscrew_actuator: (x, y) => `<rect class="glyph" x="${x - 5}" y="${y - 10}" width="10" height="20" fill="#1a7f37" stroke="#0d4a1f"/>`,
    wing_tip_brake: (x, y) => `<g class="glyph"><rect x="${x - 8}" y="${y - 10}" width="16" height="20" fill="#6f42c1" stroke="#3d2270"/><path d="M${x - 8} ${y - 10}L${x + 8} ${y + 10}M${x + 8} ${y - 10}L${x - 8} ${y + 10}" stroke="#fff"/></g>`,
    position_sensor: (x, y) => `<path class="glyph" d="M${x} ${y + 7}L${x + 7} ${y - 6}L${x - 7} ${y - 6}Z" fill="#00838f" stroke="#004d54"/>`,
    disconnector: (x, y) => `<rect class="glyph" x="${x - 4}" y="${y - 9}" width="8" height="18" fill="#c2185b" stroke="#6d0d33"/>`,
  };
  const fallbackGlyph = (x, y) => `<rect class="glyph" x="${x - 6}" y="${y - 6}" width="12" height="12" fill="#90a4ae" stroke="#455a64"/>`;

  function renderArchitecture() {
    const comps = data.components;
    const placed = comps.filter((c) => c.x != null);
    const xs = placed.map((c) => c.x);
    const xmin = Math.min(...xs, 0), xmax = Math.max(...xs, 0);
    const box = document.getElementById("architecture-drawing");
    const width = Math.max(1000, box.clientWidth - 2), margin = 40;
    const lanes = placed.map((c) => c.lane);
    const laneMin = Math.min(-1, ...lanes), laneMax = Math.max(2, ...lanes);
    const laneGap = 56, top = 36;
    const height = top + (laneMax - laneMin + 1) * laneGap + 40;
    const X = (x) => margin + (x - xmin) / Math.max(1e-9, xmax - xmin) * (width - 2 * margin);
    const Y = (lane) => top + (lane - laneMin) * laneGap + 10;
    let svg = `<svg id="architecture-svg" width="${width}" height="${height}" viewBox="0 0 ${width} ${height}" role="img" aria-label="drive system along the span">`;
    // Span axis with a tick every 5 m.
    const axisY = height - 22;
    svg += `<line x1="${X(xmin)}" y1="${axisY}" x2="${X(xmax)}" y2="${axisY}" stroke="#90a4ae"/>`;
    for (let t = Math.ceil(xmin / 5) * 5; t <= xmax; t += 5)
      svg += `<line x1="${X(t)}" y1="${axisY}" x2="${X(t)}" y2="${axisY + 4}" stroke="#90a4ae"/><text x="${X(t)}" y="${axisY + 15}" text-anchor="middle">${t} m</text>`;
    // Connections: shafts as thick lines, the rest thin.
    let edges = 0;
    const pos = (i) => { const c = comps[i]; return c.x == null ? null : [X(c.x), Y(c.lane)]; };
    for (const [a, b] of data.edges) {
      const pa = pos(a), pb = pos(b);
      if (!pa || !pb) continue;
      const shaft = comps[a].type === "torque_shaft" || comps[b].type === "torque_shaft";
      svg += `<line class="edge" x1="${pa[0]}" y1="${pa[1]}" x2="${pb[0]}" y2="${pb[1]}" stroke="${shaft ? "#37474f" : "#90a4ae"}" stroke-width="${shaft ? 4 : 1.5}"/>`;
      edges++;
    }
    // Components: glyphs (shafts: a marker at their midpoint), each a link to its parameters.
    let marks = 0;
    // Labels of neighbours closer than a label's width go on alternate rows.
    const labelRow = new Map(), lastLabel = new Map();
    const labelled = (c) => c.type !== "torque_shaft" && c.type !== "steady_bearing";
    comps.map((c, i) => i).filter((i) => pos(i) && labelled(comps[i])).sort((a, b) => pos(a)[0] - pos(b)[0]).forEach((i) => {
      const c = comps[i], x = pos(i)[0], last = lastLabel.get(c.lane);
      const row = last && x - last.x < 46 ? (last.row + 1) % 3 : 0;
      labelRow.set(i, row);
      lastLabel.set(c.lane, { x: x, row: row });
    });
    comps.forEach((c, i) => {
      const p = pos(i);
      if (!p) return;
      const glyph = c.type === "torque_shaft"
        ? `<rect class="glyph" x="${p[0] - 3}" y="${p[1] - 3}" width="6" height="6" fill="#37474f"/>`
        : (GLYPHS[c.type] || fallbackGlyph)(p[0], p[1]);
      const label = !labelled(c) ? "" :
        `<text x="${p[0]}" y="${p[1] + (c.lane < 0 ? -12 - 10 * labelRow.get(i) : 22 + 10 * labelRow.get(i))}" text-anchor="middle">${escapeXml(c.id)}</text>`;
      svg += `<a class="component" href="#c-${escapeXml(c.id)}" data-id="${escapeXml(c.id)}"><title>${escapeXml(c.id + " (" + c.type_name + ") at x = " + fmt(c.x) + " m")}</title>${glyph}${label}</a>`;
      marks++;
    });
    svg += `</svg>`;
    box.innerHTML = svg;
    state.drawing = { components: marks, edges: edges, unplaced: comps.length - marks };
    if (data.span_from_lengths) box.after(el("p", { class: "hint", text: "Span positions not given in the project were computed from the shaft lengths along the drive line." }));
    const legend = document.getElementById("architecture-legend");
    const types = [...new Set(comps.map((c) => c.type))];
    for (const t of types) {
      const g = t === "torque_shaft" ? `<line x1="0" y1="9" x2="18" y2="9" stroke="#37474f" stroke-width="4"/>` : (GLYPHS[t] || fallbackGlyph)(9, 9);
      const span = el("span");
      span.innerHTML = `<svg width="18" height="18">${g}</svg>`;
      span.append(comps.find((c) => c.type === t).type_name);
      legend.append(span);
    }
  }

  function renderComponents() {
    const finals = new Map(data.check.parameters.map((p) => [p.name, p]));
    const box = document.getElementById("components");
    for (const c of data.components) {
      const d = el("details", { class: "component", id: "c-" + c.id });
      d.append(el("summary", {}, el("strong", { text: c.id }), " \u2014 " + c.type_name + (c.x != null ? ", x = " + fmt(c.x) + " m" : "") + (c.description ? ": " + c.description : "")));
      const rows = c.parameters.map((p) => {
        if (p.text != null) return [p.name, p.text, "", "", "", "", ""];
        const f = finals.get(c.id + "." + p.name);
        const domain = p.min == null && p.max == null ? "\u2013" : "[" + fmt(p.min) + ", " + fmt(p.max) + "]";
        const narrowed = f && f.final ? "[" + fmt(f.final[0]) + ", " + fmt(f.final[1]) + "]" + (f.unit && f.unit !== p.unit ? " " + f.unit : "") : (f ? "empty" : "\u2013");
        return [p.name, fmt(p.value), domain, narrowed, p.unit, el("span", { class: "prov-" + p.provenance, text: p.provenance }), p.note];
      });
      d.append(table(["parameter", "value", "domain", "after propagation", "unit", "provenance", "source"], rows, [1]));
      box.append(d);
    }
    const open = () => {
      const id = decodeURIComponent(location.hash.slice(1));
      const target = id.startsWith("c-") ? document.getElementById(id) : null;
      if (target) { target.open = true; target.scrollIntoView({ block: "center" }); }
    };
    window.addEventListener("hashchange", open);
    open();
  }

  // ---------------------------------------------------------------------------------------- sizing
  function renderSizing() {
    const comps = new Map(data.components.map((c) => [c.id, c]));
    const capacity = new Map(data.sizing.margins.map((m) => [m.component, m.allowable_N_m]));
    const box = document.getElementById("sizing-plots");
    data.sizing.load_cases.forEach((lc, k) => {
      const shafts = lc.components.filter((t) => t.type === "torque_shaft" && comps.get(t.component) && comps.get(t.component).x != null)
        .map((t) => ({ x: comps.get(t.component).x, t: t }))
        .sort((a, b) => a.x - b.x);
      if (!shafts.length) return;
      // A gap at the PDU between the wings.
      const rows = [];
      shafts.forEach((s, i) => {
        if (i > 0 && Math.sign(shafts[i - 1].x) !== Math.sign(s.x)) rows.push([0, null, null, null, null]);
        const cap = capacity.get(s.t.component);
        rows.push([s.x, s.t.torque_N_m.nominal, s.t.torque_N_m.min, s.t.torque_N_m.max, cap == null ? null : cap]);
      });
      const cols = [0, 1, 2, 3, 4].map((c) => rows.map((r) => r[c]));
      const color = COLORS[k % COLORS.length];
      plot(box, "sizing-" + lc.name, "Load case " + lc.name + " (" + lc.direction + "): shaft torque along the span [N*m]", cols, [
        { label: "nominal", stroke: color, width: 2, points: { show: true, size: 5 } },
        { label: "enclosure min", stroke: color + "66", dash: [4, 4] },
        { label: "enclosure max", stroke: color + "66", dash: [4, 4] },
        { label: "capacity", stroke: "#b3261e", width: 1.5, points: { show: true, size: 4 } },
      ], { bands: [{ series: [3, 2], fill: color + "22" }], axes: [{ label: "span position x [m]" }, { label: "N*m", size: 70 }],
           scales: { x: { time: false } } });
    });
    const tables = document.getElementById("sizing-tables");
    tables.append(el("h3", { text: "PDU per load case" }));
    tables.append(table(["load case", "direction", "PDU speed [rad/s]", "PDU torque [N*m]", "enclosure", "output power [W]", "input power [W]"],
      data.sizing.load_cases.map((lc) => [lc.name, lc.direction, fmt(lc.pdu_speed_rad_s), fmt(lc.pdu_torque_N_m.nominal),
        "[" + fmt(lc.pdu_torque_N_m.min) + ", " + fmt(lc.pdu_torque_N_m.max) + "]", fmt(lc.pdu_power_W.nominal), fmt(lc.pdu_input_power_W.nominal)]), [2, 3, 5, 6]));
    tables.append(el("h3", { text: "Limiter and brake settings" }));
    tables.append(table(["component", "parameter", "rule", "operating [N*m]", "recommended [N*m]", "current [N*m]", "factor", "within rule"],
      data.sizing.settings.map((s) => [componentLink(s.component), s.parameter, s.rule, fmt(s.operating_N_m.nominal), fmt(s.recommended_N_m),
        fmt(s.current_N_m), fmt(s.current_factor, 3), el("span", { class: s.ok ? "" : "bad", text: s.ok ? (s.robust ? "yes" : "yes (not over the whole enclosure)") : "no" })]), [3, 4, 5, 6]));
  }

  // ---------------------------------------------------------------------------------------- modes
  function renderModes() {
    const models = data.modes.models;
    const n = Math.max(...models.map((m) => m.clamped_hz.length));
    const rows = [];
    for (const m of models) {
      rows.push([m.reduction, m.degrees_of_freedom, "clamped", ...Array.from({ length: n }, (_, i) => fmt(m.clamped_hz[i])), percent(m.first_clamped_error)]);
      rows.push([m.reduction, m.degrees_of_freedom, "free", ...Array.from({ length: n }, (_, i) => fmt(m.free_hz[i])), percent(m.first_free_error)]);
    }
    const headers = ["model", "DOF", "PDU", ...Array.from({ length: n }, (_, i) => "f" + (i + 1) + " [Hz]"), "first-mode error"];
    document.getElementById("modes-table").append(table(headers, rows, [1, 3, 4, 5, 6, 7, 8, 9]));
    const box = document.getElementById("modes-plots");
    // Shapes along the drive line: nodes with a span position, sorted, a gap at the PDU.
    const along = (m, k) => {
      const pts = [];
      m.nodes.forEach((_, i) => { if (m.node_x[i] != null && m.clamped_shapes[k]) pts.push([m.node_x[i], m.clamped_shapes[k][i]]); });
      pts.sort((a, b) => a[0] - b[0]);
      return pts;
    };
    const merge = (lines) => {
      const xs = [...new Set(lines.flatMap((l) => l.map((p) => p[0])))].sort((a, b) => a - b);
      const index = new Map(xs.map((x, i) => [x, i]));
      const cols = [xs];
      for (const l of lines) {
        const c = new Array(xs.length).fill(null);
        for (const [x, y] of l) if (c[index.get(x)] == null) c[index.get(x)] = y;
        cols.push(c);
      }
      return cols;
    };
    const full = models[0];
    const shapes = full.clamped_shapes.slice(0, 3).map((_, k) => along(full, k));
    plot(box, "modes-full", "First mode shapes of the " + full.reduction + " model, PDU clamped (twist angle, max |.| = 1) along the span",
      merge(shapes), shapes.map((_, k) => ({ label: "mode " + (k + 1) + " (" + fmt(full.clamped_hz[k]) + " Hz)", stroke: COLORS[k], width: 2, spanGaps: false })),
      { axes: [{ label: "span position x [m]" }, { label: "shape" }], scales: { x: { time: false } } });
    const firsts = models.map((m) => along(m, 0));
    plot(box, "modes-first", "First mode shape, PDU clamped: full resolution beside the reduced models",
      merge(firsts), models.map((m, k) => ({ label: m.reduction + " (" + fmt(m.clamped_hz[0]) + " Hz)", stroke: COLORS[k], width: k ? 1.5 : 2.5,
        spanGaps: true, points: { show: true, size: k ? 6 : 3 } })),
      { axes: [{ label: "span position x [m]" }, { label: "shape" }], scales: { x: { time: false } } });
  }

  // ---------------------------------------------------------------------------------------- peaks
  function renderPeaks() {
    const cases = data.peak_cases;
    const idx = cases.map((_, i) => i);
    const single = cases.map((c) => c.single_dof.nominal);
    const transient = cases.map((c) => (c.transient && c.transient.ok ? c.transient.value : null));
    const cap = cases.map((c) => (c.capacity ? c.capacity.value : null));
    const series = [
      { label: "single-DOF estimate [N*m]", fill: "#0b5cad99", stroke: "#0b5cad", paths: bars("peaks-plot", -1, 0.34), points: { show: false } },
      { label: "transient simulation [N*m]", fill: "#d1462f99", stroke: "#d1462f", paths: bars("peaks-plot", 1, 0.34), points: { show: false } },
      { label: "capacity on the load path [N*m]", stroke: "#1d2329", width: 0, paths: () => null, points: { show: true, size: 9, fill: "#1d2329", stroke: "#1d2329" } },
    ];
    const cols = [idx, single, transient, cap];
    plot(document.getElementById("peaks-plot"), "peaks-plot", "Peak torque per sizing case, at the shaft speed", cols, series, {
      height: 380,
      padding: [12, 60, 0, 0],
      scales: { x: { time: false, range: [-0.7, cases.length - 0.3] }, y: { range: (u, min, max) => [0, max * 1.08] } },
      axes: [{ rotate: -60, size: 120, space: 10, incrs: [1], values: (u, splits) => splits.map((s) => (Number.isInteger(s) && cases[s] ? cases[s].name : "")) },
             { label: "N*m", size: 70 }],
    });
    document.getElementById("peaks-table").append(table(
      ["case", "kind", "acts at", "single-DOF [N*m]", "enclosure", "widened most by", "transient [N*m]", "at", "t [s]", "transient / single-DOF", "capacity [N*m]", "weakest", "status"],
      cases.map((c) => {
        const t = c.transient;
        const ratio = t && t.ok && c.single_dof.nominal ? t.value / c.single_dof.nominal : null;
        const over = c.capacity && t && t.value > c.capacity.value;
        const widest = (c.ranking || []).map((r) => r.parameter + " " + Math.round(r.share * 100) + " %").join(", ");
        return [c.name, c.kind, componentLink(c.acts_at), fmt(c.single_dof.nominal), "[" + fmt(c.single_dof.min) + ", " + fmt(c.single_dof.max) + "]", widest,
          t ? el("span", { class: over ? "bad" : "", text: fmt(t.value) }) : "not simulated", t ? componentLink(t.at) : "\u2013", t ? fmt(t.time) : "\u2013",
          fmt(ratio, 3), c.capacity ? fmt(c.capacity.value) : "\u2013", c.capacity ? componentLink(c.capacity.component) : "\u2013",
          t ? (t.ok ? (t.passivity && t.passivity !== "passive" ? el("span", { class: "bad", text: "ok; " + t.passivity }) : "ok")
                    : el("span", { class: "bad", text: "failed: " + t.message })) : "\u2013"];
      }), [3, 6, 8, 9, 10]));
  }

  // Per component: the single-DOF value beside the largest simulated torque of any sizing case, and
  // whether the single-DOF value bounds it (`highlift peak --transient`, "transient_components").
  function renderPeakComponents() {
    const rows = data.peak_components || [];
    const box = document.getElementById("peaks-components");
    if (!rows.length) {
      box.append(el("p", { class: "hint", text: "No transient simulations in this report: the per-component bound check needs them." }));
      return;
    }
    const exceeded = rows.filter((r) => !r.bound).length;
    box.append(el("h3", { text: "Single-DOF value against the simulation, per component" }));
    box.append(el("p", { class: exceeded ? "bad" : "hint", text: exceeded
      ? exceeded + " component(s) where the simulation exceeds the single-DOF value: there it is NOT A BOUND."
      : "The single-DOF value bounds the simulated torque of every component." }));
    box.append(table(["component", "single-DOF [N*m]", "its case", "transient [N*m]", "its case", "single-DOF value"],
      rows.map((r) => [componentLink(r.component), fmt(r.single_dof), r.single_dof_case, fmt(r.transient), r.transient_case || "\u2013",
        r.bound ? "bound" : el("span", { class: "bad", text: r.flag })]), [1, 3]));
  }

  // ---------------------------------------------------------------------------------------- campaign
  // The envelope of a design-load campaign (`highlift report --campaign DIR`): per component the
  // largest |torque| of any case and sample beside its capacity, at the component's own speed.
  function renderCampaign() {
    const box = document.getElementById("campaign");
    const c = data.campaign;
    if (!c) {
      box.append(el("p", { class: "hint", text: "No design-load campaign in this report: run `highlift campaign PROJECT --out DIR` " +
        "(every failure case over the parameter domains) and `highlift report PROJECT --campaign DIR` to add its envelope here." }));
      return;
    }
    box.append(el("h3", { text: "Design-load envelope over the campaign" }));
    box.append(el("p", { class: "hint", text: c.brief + ". Model: " + c.model + "; " + c.cases + " cases x " + c.samples_per_case +
      " samples" + (c.parameters.length ? " over " + c.parameters.join(", ") : "") + ". Torques at each component's own speed." }));
    if (!c.complete) box.append(el("p", { class: "bad", text: "Incomplete: " + c.runs_done + " of " + c.runs_total +
      " runs are in the results; run the same `highlift campaign` command again to resume it." }));
    const rows = c.envelope;
    const idx = rows.map((_, i) => i);
    const load = rows.map((e) => Math.abs(e.torque_N_m));
    const cap = rows.map((e) => (e.capacity_N_m > 0 ? e.capacity_N_m : null));
    plot(box, "campaign-envelope", "Largest |torque| per component over every case and sample, beside its capacity", [idx, load, cap], [
      { label: "envelope |torque| [N*m]", fill: "#d1462f99", stroke: "#d1462f", paths: bars("campaign-envelope", 0, 0.6), points: { show: false } },
      { label: "capacity [N*m]", stroke: "#1d2329", width: 0, paths: () => null, points: { show: true, size: 9, fill: "#1d2329", stroke: "#1d2329" } },
    ], {
      height: 360,
      padding: [12, 60, 0, 0],
      scales: { x: { time: false, range: [-0.7, rows.length - 0.3] }, y: { range: (u, min, max) => [0, max * 1.08] } },
      axes: [{ rotate: -60, size: 110, space: 10, incrs: [1], values: (u, splits) => splits.map((s) => (Number.isInteger(s) && rows[s] ? rows[s].component : "")) },
             { label: "N*m", size: 70 }],
    });
    box.append(el("div", { id: "campaign-envelope-table" }, table(
      ["component", "|torque| [N*m]", "case", "sample", "t [s]", "capacity [N*m]", "capacity", "margin"],
      rows.map((e) => [componentLink(e.component), fmt(Math.abs(e.torque_N_m)), e.case, e.sample_label || String(e.sample), fmt(e.time_s),
        e.capacity_N_m > 0 ? fmt(e.capacity_N_m) : "\u2013", e.capacity_name || "\u2013",
        el("span", { class: e.margin != null && e.margin < 0 ? "bad" : "", text: percent(e.margin) })]), [1, 4, 5, 7])));
    box.append(el("div", { id: "campaign-cases-table" }, table(
      ["case", "kind", "load case", "runs", "failed", "largest peak [N*m]", "at", "sample", "t [s]", "single-DOF, nominal [N*m]", "single-DOF, largest [N*m]"],
      c.case_peaks.map((k) => [k.case, k.kind, k.load_case || "\u2013", String(k.runs), el("span", { class: k.failures ? "bad" : "", text: String(k.failures) }),
        fmt(k.peak_N_m), componentLink(k.at), String(k.sample), fmt(k.time_s), fmt(k.single_dof_N_m), fmt(k.single_dof_max_N_m)]), [3, 4, 5, 7, 8, 9, 10])));
    if (c.failed.length)
      box.append(el("div", { id: "campaign-failed-table" }, table(["run", "case", "sample", "message"],
        c.failed.map((f) => [String(f.run), f.case, String(f.sample), f.message]), [0, 2])));
  }

  // ---------------------------------------------------------------------------------------- scenarios
  function renderScenarios() {
    const box = document.getElementById("scenario-plots");
    for (const s of data.scenarios) {
      const div = el("div", { class: "scenario", id: "scenario-" + s.name });
      div.append(el("h3", { text: s.name + " (" + s.kind + (s.load_case ? ", load case " + s.load_case : "") + ")" }));
      div.append(el("p", { class: "hint", text: (s.description || "") + " Simulated " + fmt(s.stop_time) + " s, " + s.states + " states, " +
        s.events + " events, " + fmt(s.wall_seconds, 2) + " s of computing; " + s.time.length + " of " + s.rows_simulated + " output rows kept (each bucket's extremes)." }));
      if (!s.ok) div.append(el("p", { class: "bad", text: "The simulation failed: " + s.message }));
      if (s.passivity && s.passivity !== "passive") div.append(el("p", { class: "bad", text: "Passivity monitor: " + s.passivity }));
      box.append(div);
      const group = { plots: [] };
      const sync = (u) => {
        for (const other of group.plots) if (other !== u && (other.scales.x.min !== u.scales.x.min || other.scales.x.max !== u.scales.x.max))
          other.setScale("x", { min: u.scales.x.min, max: u.scales.x.max });
      };
      for (const [kind, title, unit] of [["speed", "speeds", "rad/s"], ["torque", "torques", "N*m"], ["state", "monitor: wing-tip brake command", ""]]) {
        const signals = s.signals.filter((g) => g.group === kind);
        if (!signals.length) continue;
        const u = plot(div, "scenario-" + s.name + "-" + kind, s.name + ": " + title + (unit ? " [" + unit + "]" : ""), [s.time, ...signals.map((g) => g.values)],
          signals.map((g, k) => ({ label: g.name, stroke: COLORS[k % COLORS.length], width: 1.5, paths: kind === "state" ? uPlot.paths.stepped({ align: 1 }) : undefined })),
          { height: kind === "state" ? 150 : 260, cursor: { sync: { key: "scenario-" + s.name }, drag: { x: true, y: false } },
            scales: { x: { time: false } }, axes: [{ label: "time [s]" }, { label: unit, size: 70 }],
            hooks: { setScale: [(u, key) => { if (key === "x") sync(u); }] } });
        group.plots.push(u);
      }
    }
  }

  function renderFooter() {
    const t = data.timings;
    document.getElementById("meta").textContent = (data.project.file || "") + " \u2014 " + data.components.length + " components, " +
      data.requirements.length + " requirements, " + data.scenarios.length + " scenarios simulated";
    document.getElementById("description").textContent = data.project.description || "";
    document.getElementById("footer").textContent = "Generated by " + data.generator + ". Analyses " + fmt(t.total - t.simulations, 3) + " s, " +
      t.simulation_count + " simulations in " + fmt(t.simulations, 3) + " s of wall time (" + fmt(t.simulated, 3) + " s of computing). " +
      "Plots: uPlot (MIT licence), inlined; this file refers to nothing outside itself.";
  }

  const sections = [renderSummary, renderSynthesis, renderArchitecture, renderComponents, renderSizing, renderModes, renderPeaks, renderPeakComponents, renderCampaign, renderScenarios, renderFooter];
  for (const render of sections) {
    try { render(); } catch (e) { state.errors.push(render.name + ": " + e.message); console.error(render.name, e); }
  }
  state.ready = true;
})();
