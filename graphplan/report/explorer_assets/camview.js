// graphplan explorer of a cam: draws the data Python computed (no solver here). Plain ES2017, no library.
"use strict";
(function () {
  const D = JSON.parse(document.getElementById("explorer-data").textContent);
  const NS = "http://www.w3.org/2000/svg";
  const $ = (id) => document.getElementById(id);
  const WORDS = {
    en: {
      play: "▶ play", pause: "⏸ pause", playName: "play or pause the turn (Space)", prev: "one step back (←)",
      next: "one step forward (→)", slider: "the cam's turn φ", divisions: "the construction's divisions",
      mech: "The cam turning, the follower moving (μ_l = {mu} m/mm): the pressure angle ϑ between the normal at the contact and the follower's velocity",
      phase: "Phase diagram: s against ds/dφ (at the scale of s); the line from the cam's centre makes ϑ with the follower's axis",
      phaseRocking: "Phase diagram: the arm's angle against dψ/dφ (both at the profile's scale, × l)",
      diagrams: "s, ds/dφ, d²s/dφ² against φ (dots: the construction at the divisions; red: the current turn)",
      zoom: "Wheel or drag on a drawing; on a focused drawing (Tab) + and − zoom, the arrows move it, 0 fits it; on the diagrams ← → seek the turn.",
      zoomKeys: "keys: + and − zoom, the arrows move, 0 shows the whole drawing",
      phi: "φ = {a}°", s: "s = {v}", theta: "ϑ = {a}°", thetaG: "graphically ϑ = {a}° (division {k})",
      values: "At the divisions (as graphplan cam --json)", note: "exact beside the construction's reading (ruler {p} mm, protractor ½°)",
      head: ["division", "φ, °", "s exact", "s graph.", "ds/dφ exact", "ds/dφ graph.", "ϑ exact, °", "ϑ graph., °"],
      warnings: "Warnings", none: "none",
      replay: "The profile by inversion, step by step", back: "◀ back", forward: "forward ▶", first: "first step (Home)",
      last: "last step (End)", backName: "one step back (←)", forwardName: "one step forward (→)", step: "step {k} of {n}",
      facts: "{f}; laws: rise {r}, return {t}; phases {p}°; ω = {w} rad/s; R_0 = {R} mm (smallest {m} mm); [ϑ] = {ar}°, {at}°",
      translating: "translating follower, e = {e} mm", rocking: "rocking follower, l = {l} mm, a = {a} mm",
      footer: "graphplan explorer: one offline file, no network access; the values are graphplan cam's exact solution and construction.",
      langs: "language", rise: "rise", ret: "return",
    },
    uk: {
      play: "▶ пуск", pause: "⏸ пауза", playName: "пуск або пауза обертання (пробіл)", prev: "на крок назад (←)",
      next: "на крок вперед (→)", slider: "поворот кулачка φ", divisions: "поділки побудови",
      mech: "Кулачок обертається, штовхач рухається (μ_l = {mu} м/мм): кут тиску ϑ між нормаллю в точці контакту і швидкістю штовхача",
      phase: "Фазова діаграма: s від ds/dφ (у масштабі s); пряма з центра кулачка утворює ϑ з віссю штовхача",
      phaseRocking: "Фазова діаграма: кут коромисла від dψ/dφ (обидва в масштабі профілю, × l)",
      diagrams: "s, ds/dφ, d²s/dφ² від φ (точки: побудова на поділках; червоне: поточний поворот)",
      zoom: "Коліщатко або перетягування на кресленні; на вибраному (Tab) + і − — масштаб, стрілки — зсув, 0 — усе; на діаграмах ← → — поворот.",
      zoomKeys: "клавіші: + і − масштаб, стрілки зсувають, 0 показує все креслення",
      phi: "φ = {a}°", s: "s = {v}", theta: "ϑ = {a}°", thetaG: "графічно ϑ = {a}° (поділка {k})",
      values: "На поділках (як graphplan cam --json)", note: "точно поруч із відліком побудови (лінійка {p} мм, транспортир ½°)",
      head: ["поділка", "φ, °", "s точно", "s граф.", "ds/dφ точно", "ds/dφ граф.", "ϑ точно, °", "ϑ граф., °"],
      warnings: "Попередження", none: "немає",
      replay: "Профіль методом обернення руху, крок за кроком", back: "◀ назад", forward: "вперед ▶", first: "перший крок (Home)",
      last: "останній крок (End)", backName: "на крок назад (←)", forwardName: "на крок вперед (→)", step: "крок {k} з {n}",
      facts: "{f}; закони: підйом — {r}, опускання — {t}; фази {p}°; ω = {w} рад/с; R_0 = {R} мм (найменший {m} мм); [ϑ] = {ar}°, {at}°",
      translating: "поступальний штовхач, e = {e} мм", rocking: "коромисловий штовхач, l = {l} мм, a = {a} мм",
      footer: "graphplan explorer: один офлайн-файл, без мережі; значення — точний розв'язок і побудова graphplan cam.",
      langs: "мова", rise: "підйом", ret: "опускання",
    },
  };
  const UNITS = { uk: { "m": "м", "mm": "мм", "°": "°" }, en: {} };
  let lang = D.lang === "en" ? "en" : "uk";
  const W = () => WORDS[lang];
  const unit = (u) => UNITS[lang][u] || u;
  const fill = (s, f) => s.replace(/\{(\w+)\}/g, (m, k) => (k in f ? f[k] : m));
  const tr = (v) => (v && typeof v === "object" ? (v[lang] !== undefined ? v[lang] : v.en) : v);

/*{{helpers}}*/

  // -- the grid of the cam's turn ------------------------------------------------------------------------------
  const G = D.grid, N = G.phi.length;
  let index = 0, timer = null;
  const nearest = (phi) => { let b = 0; for (let i = 0; i < N; i++) if (Math.abs(G.phi[i] - phi) < Math.abs(G.phi[b] - phi)) b = i; return b; };
  const divisionAt = {};
  D.divisions.forEach((d, k) => { const i = nearest(d.phi); if (Math.abs(G.phi[i] - d.phi) < 1e-6 && !(i in divisionAt)) divisionAt[i] = k; });
  const sUnit = D.rocking ? "°" : "m";
  const rot = (p, a) => [p[0] * Math.cos(a) - p[1] * Math.sin(a), p[0] * Math.sin(a) + p[1] * Math.cos(a)];

  // -- the mechanism: the cam turned by φ in its sense, the follower at the grid's position ---------------------
  const mechSvg = $("mech");
  const mechZ = Zoomable(mechSvg, () => drawMech(index));
  const mechBox = [1e9, 1e9, -1e9, -1e9];
  D.profile.working.forEach((p) => { grow(mechBox, p); grow(mechBox, [-p[0], -p[1]]); grow(mechBox, [p[1], p[0]]); });
  G.C.forEach((p) => grow(mechBox, p));
  if (D.pivot) grow(mechBox, D.pivot);
  if (!D.rocking) { const top = G.C.reduce((m, p) => Math.max(m, p[1]), 0); grow(mechBox, [G.C[0][0], top + 20]); }
  function drawMech(i) {
    clear(mechSvg);
    const px = mechZ.px(), g = el("g", {}, mechSvg), segs = [];
    const a = D.sense * G.phi[i] * Math.PI / 180;
    const R0 = D.R0 / D.mu_l;
    el("circle", { cx: 0, cy: 0, r: r3(R0), class: "cam-base" }, g);
    poly(g, D.profile.working.map((p) => rot(p, a)), "cam-body", true);
    if (D.roller > 0) poly(g, D.profile.centre.map((p) => rot(p, a)), "cam-centre", true);
    line(g, [0, 0], rot([R0 * 0.6, 0], a), "follower");
    el("circle", { cx: 0, cy: 0, r: r3(4 * px), class: "joint" }, g);
    const C = G.C[i], K = G.contact[i], u = G.u[i];
    if (D.rocking) {
      line(g, D.pivot, C, "follower");
      el("circle", { cx: r3(D.pivot[0]), cy: r3(-D.pivot[1]), r: r3(4 * px), class: "joint" }, g);
      segs.push([D.pivot, C]);
    } else {
      const top = [C[0], C[1] + 40 + D.roller / D.mu_l];
      line(g, C, top, "follower");
      segs.push([C, top]);
      line(g, [C[0] - 5, top[1] - 12], [C[0] - 5, top[1] + 4], "ground");
      line(g, [C[0] + 5, top[1] - 12], [C[0] + 5, top[1] + 4], "ground");
    }
    if (D.roller > 0) el("circle", { cx: r3(C[0]), cy: r3(-C[1]), r: r3(D.roller / D.mu_l), class: "roller" }, g);
    // the pressure angle at the contact: the normal (contact → roller centre) and the follower's velocity u
    const nx = C[0] - K[0], ny = C[1] - K[1], nn = Math.hypot(nx, ny) || 1, L = 60 * px;
    const n = D.roller > 0 ? [nx / nn, ny / nn] : normalOfKnife(i);
    line(g, K, [K[0] + n[0] * L, K[1] + n[1] * L], "normal");
    line(g, K, [K[0] + u[0] * L, K[1] + u[1] * L], "axisline");
    segs.push([K, [K[0] + n[0] * L, K[1] + n[1] * L]], [K, [K[0] + u[0] * L, K[1] + u[1] * L]]);
    const t0 = Math.atan2(u[1], u[0]), t1 = Math.atan2(n[1], n[0]);
    let d = t1 - t0; while (d > Math.PI) d -= 2 * Math.PI; while (d < -Math.PI) d += 2 * Math.PI;
    const arc = [];
    for (let k = 0; k <= 16; k++) { const t = t0 + d * k / 16; arc.push([K[0] + 0.7 * L * Math.cos(t), K[1] + 0.7 * L * Math.sin(t)]); }
    if (Math.abs(d) > 1e-3) poly(g, arc, "angle", false);
    el("circle", { cx: r3(K[0]), cy: r3(-K[1]), r: r3(3 * px), class: "contact" }, g);
    const labels = [{ at: [0, 0], text: "O" }, { at: arc[8], text: "ϑ = " + fx(Math.abs(G.theta[i]), 1) + "°", cls: "new" }];
    if (D.rocking) labels.push({ at: D.pivot, text: "O_1" });
    placeLabels(el("g", { id: "mech-labels" }, mechSvg), labels, segs, px);
    mechSvg.setAttribute("data-theta", String(G.theta[i]));
    mechSvg.setAttribute("data-angle", String(Math.abs(d) * 180 / Math.PI));
  }
  function normalOfKnife(i) {                 // a knife edge: the profile's normal from its neighbours
    const a = D.sense * G.phi[i] * Math.PI / 180, P = D.profile.centre, n = P.length;
    const k = Math.round((G.phi[i] / 360) * (n - 1)), p0 = rot(P[(k - 1 + n - 1) % (n - 1)], a), p1 = rot(P[(k + 1) % (n - 1)], a);
    const t = [p1[0] - p0[0], p1[1] - p0[1]], m = Math.hypot(t[0], t[1]) || 1;
    const out = [t[1] / m, -t[0] / m], C = G.C[i];
    return out[0] * C[0] + out[1] * C[1] >= 0 ? out : [-out[0], -out[1]];
  }

  // -- the phase diagram with the running point ---------------------------------------------------------------
  const phaseSvg = $("phase");
  const phaseZ = Zoomable(phaseSvg, () => drawPhase(index));
  const phaseBox = [0, 0, 0, 0];
  for (let i = 0; i < N; i++) grow(phaseBox, [G.phase_x[i], G.phase_y[i]]);
  if (D.phase_centre) grow(phaseBox, D.phase_centre);
  function drawPhase(i) {
    clear(phaseSvg);
    const px = phaseZ.px(), g = el("g", {}, phaseSvg), segs = [];
    line(g, [phaseBox[0], 0], [phaseBox[2], 0], "axis");
    line(g, [0, Math.min(0, phaseBox[1])], [0, phaseBox[3]], "axis");
    poly(g, G.phase_x.map((x, k) => [x, G.phase_y[k]]), "phase-curve", true);
    const P = [G.phase_x[i], G.phase_y[i]];
    const labels = [];
    if (D.phase_centre) {
      const O = D.phase_centre;
      line(g, O, P, "phase-ray");
      line(g, O, [O[0], Math.max(P[1], O[1] + 10)], "axisline");
      segs.push([O, P]);
      el("circle", { cx: r3(O[0]), cy: r3(-O[1]), r: r3(3.5 * px), class: "joint" }, g);
      labels.push({ at: O, text: "O" });
    }
    el("circle", { cx: r3(P[0]), cy: r3(-P[1]), r: r3(5 * px), class: "contact", id: "phase-point" }, g);
    labels.push({ at: P, text: "ϑ = " + fx(Math.abs(G.theta[i]), 1) + "°", cls: "new",
      prefer: [(phaseBox[0] + phaseBox[2]) / 2 - P[0], (phaseBox[1] + phaseBox[3]) / 2 - P[1]] });
    placeLabels(el("g", {}, phaseSvg), labels, segs, px);
  }

  // -- the s, ds/dφ, d²s/dφ² diagrams in screen pixels, the cursor; click, drag or ← → to seek -------------------
  const dsvg = $("diagrams");
  let DX = { x0: 0, w: 1 }, cursor = null;
  function drawDiagrams() {
    clear(dsvg);
    const width = Math.max(260, dsvg.clientWidth || 400), size = LETTER, left = 70, right = 26;
    const CH = Math.max(70, Math.round(((dsvg.clientHeight || width) - 60) / 3) - 22), GAP = 22, WIDTH = width - left - right;
    DX = { x0: left, w: WIDTH };
    dsvg.setAttribute("viewBox", [0, 0, width, 3 * (CH + GAP) + 40].join(" "));
    dsvg.setAttribute("data-x0", String(left));
    dsvg.setAttribute("data-width", String(WIDTH));
    const names = [["s", sUnit], ["ds/dφ", sUnit], ["d²s/dφ²", sUnit]];
    ["s", "v", "a"].forEach((key, row) => {
      const y0 = 6 + row * (CH + GAP), ex = G[key];
      const dots = D.divisions.map((d) => [d.phi, key === "s" ? d.s_g : key === "v" ? d.v_g : d.a_g]);
      let lo = Math.min(0, ...ex, ...dots.map((p) => p[1])), hi = Math.max(0, ...ex, ...dots.map((p) => p[1]));
      if (hi - lo < 1e-12) hi = lo + 1;
      const X = (t) => left + (t / 360) * WIDTH, Y = (v) => y0 + CH - ((v - lo) / (hi - lo)) * CH;
      const g = el("g", {}, dsvg);
      el("line", { x1: left, y1: y0, x2: left, y2: y0 + CH, class: "axis" }, g);
      el("line", { x1: left, y1: r3(Y(0)), x2: left + WIDTH, y2: r3(Y(0)), class: "axis" }, g);
      el("polyline", { points: G.phi.map((p, i) => r3(X(p)) + "," + r3(Y(ex[i]))).join(" "), class: "curve" }, g);
      dots.forEach((p) => el("circle", { cx: r3(X(p[0])), cy: r3(Y(p[1])), r: 2.5, class: "chord" }, g));
      const t1 = el("text", { x: left + 6, y: y0 + size, class: "dtext" }, g);
      svgMarkup(t1, names[row][0] + ", " + unit(names[row][1]) + (row ? "/" + (lang === "uk" ? "рад" : "rad") + (row > 1 ? "²" : "") : ""), size);
      const t2 = el("text", { x: left - 4, y: y0 + size * 0.8, class: "dtext", "text-anchor": "end" }, g); t2.textContent = fmtG(hi, 3);
      const t3 = el("text", { x: left - 4, y: y0 + CH, class: "dtext", "text-anchor": "end" }, g); t3.textContent = fmtG(lo, 3);
    });
    const base = 6 + 3 * (CH + GAP) - GAP;
    for (let t = 0; t <= 360; t += 90) {
      const tx = el("text", { x: r3(left + (t / 360) * WIDTH), y: base + size + 2, class: "dtext", "text-anchor": "middle" }, dsvg);
      tx.textContent = String(t) + "°";
    }
    cursor = el("line", { x1: 0, y1: 4, x2: 0, y2: base + 2, class: "cursor", id: "diagram-cursor" }, dsvg);
    moveCursor();
  }
  function moveCursor() {
    if (!cursor) return;
    const x = r3(DX.x0 + (G.phi[index] / 360) * DX.w);
    cursor.setAttribute("x1", x); cursor.setAttribute("x2", x);
  }
  let seeking = false;
  function seek(ev) {
    const p = dsvg.createSVGPoint(); p.x = ev.clientX; p.y = ev.clientY;
    const q = p.matrixTransform(dsvg.getScreenCTM().inverse());
    show(nearest(Math.min(359.999, Math.max(0, ((q.x - DX.x0) / DX.w) * 360))));
  }
  dsvg.addEventListener("pointerdown", (ev) => { seeking = true; dsvg.setPointerCapture(ev.pointerId); seek(ev); });
  dsvg.addEventListener("pointermove", (ev) => { if (seeking) seek(ev); });
  dsvg.addEventListener("pointerup", () => { seeking = false; });
  dsvg.setAttribute("tabindex", "0");
  dsvg.addEventListener("keydown", (ev) => {
    const by = { ArrowRight: 1, ArrowUp: 1, ArrowLeft: -1, ArrowDown: -1 }[ev.key];
    if (by) stepBy(by); else if (ev.key === "Home") show(0); else if (ev.key === "End") show(N - 1); else return;
    ev.preventDefault(); ev.stopPropagation();
  });

  // -- the table of the divisions, the warnings -------------------------------------------------------------------
  function drawTable() {
    const head = $("values").querySelector("thead"), body = $("values").querySelector("tbody");
    head.textContent = ""; body.textContent = "";
    const hr = document.createElement("tr");
    W().head.forEach((h) => { const th = document.createElement("th"); setMarkup(th, h); hr.appendChild(th); });
    head.appendChild(hr);
    D.divisions.forEach((d, k) => {
      const tr_ = document.createElement("tr");
      tr_.setAttribute("data-division", String(k));
      const cells = [String(k), fx(d.phi, 1), fmtG(d.s, 4), fmtG(d.s_g, 4), fmtG(d.v, 4), fmtG(d.v_g, 4), fx(d.theta, 2), fx(d.theta_g, 1)];
      cells.forEach((c, j) => { const td = document.createElement(j ? "td" : "th"); td.textContent = c; if (j === 6) td.setAttribute("data-value", String(d.theta)); tr_.appendChild(td); });
      body.appendChild(tr_);
    });
    const ul = $("warnings"); ul.textContent = "";
    const ws = tr(D.warnings);
    (ws.length ? ws : [W().none]).forEach((s) => { const li = document.createElement("li"); setMarkup(li, s); if (!ws.length) li.setAttribute("data-kind", "none"); ul.appendChild(li); });
  }

  // -- the profile by inversion, step by step -----------------------------------------------------------------------
  const rsvg = $("replay");
  const replayZ = Zoomable(rsvg, () => showStep());
  let stepNo = 0;
  const steps = D.steps;
  function showStep() {
    clear(rsvg);
    const px = replayZ.px(), g = el("g", {}, rsvg), R0 = D.R0 / D.mu_l, segs = [], labels = [{ at: [0, 0], text: "O" }];
    el("circle", { cx: 0, cy: 0, r: r3(R0), class: "cam-base" + (stepNo === 0 ? " inv-new" : "") }, g);
    if (!D.rocking && D.e) el("circle", { cx: 0, cy: 0, r: r3(Math.abs(D.e) / D.mu_l), class: "cam-base" + (stepNo === 0 ? " inv-new" : "") }, g);
    if (D.rocking) el("circle", { cx: 0, cy: 0, r: r3(D.centre_distance / D.mu_l), class: "cam-base" + (stepNo === 0 ? " inv-new" : "") }, g);
    el("circle", { cx: 0, cy: 0, r: r3(3 * px), class: "joint" }, g);
    const pts = [];
    steps.forEach((s, k) => {
      if (k > stepNo || s.draw.kind !== "point") return;
      const d = s.draw, now = k === stepNo ? " inv-new" : "";
      if (d.pivot) { line(g, [0, 0], d.pivot, "inv-axis" + now); line(g, d.pivot, d.at, "inv-axis" + now); }
      else {
        const far = [d.at[0] + d.axis[0] * 25, d.at[1] + d.axis[1] * 25];
        line(g, [d.base[0] - d.axis[0] * 8, d.base[1] - d.axis[1] * 8], far, "inv-axis" + now);
      }
      line(g, d.base, d.at, "inv-curve" + now);
      el("circle", { cx: r3(d.at[0]), cy: r3(-d.at[1]), r: r3((now ? 4 : 2.5) * px), class: "inv-point" + now }, g);
      segs.push([d.base, d.at]);
      pts.push(d.at);
      if (now || k === 1 || k === steps.length - 3) labels.push({ at: d.at, text: String(d.k), cls: now ? "new" : "" });
    });
    const done = (kind) => steps.findIndex((s) => s.draw.kind === kind) <= stepNo;
    if (done("centre")) poly(g, D.profile.centre, "inv-curve" + (steps[stepNo].draw.kind === "centre" ? " inv-new" : ""), true);
    if (done("working")) {
      const now = steps[stepNo].draw.kind === "working" ? " inv-new" : "";
      if (D.roller > 0) for (let k = 0; k < D.profile.centre.length; k += 24) {
        const c = D.profile.centre[k];
        el("circle", { cx: r3(c[0]), cy: r3(-c[1]), r: r3(D.roller / D.mu_l), class: "inv-roller" }, g);
      }
      poly(g, D.profile.working, "inv-curve" + now, true);
    }
    placeLabels(el("g", { id: "replay-labels" }, rsvg), labels, segs, px);
    setMarkup($("step-caption"), tr(steps[stepNo].caption));
    const c = $("step-count");
    c.textContent = fill(W().step, { k: stepNo, n: steps.length - 1 });
    c.setAttribute("data-step", String(stepNo));
    const ol = $("step-list");
    Array.from(ol.children).forEach((li, n) => {
      li.className = n < stepNo ? "done" : n === stepNo ? "current" : "todo";
      const b = li.querySelector("button");
      if (n === stepNo) b.setAttribute("aria-current", "step"); else b.removeAttribute("aria-current");
    });
    const cur = ol.children[stepNo];
    if (cur) {
      if (cur.offsetTop < ol.scrollTop) ol.scrollTop = Math.max(0, cur.offsetTop - 4);
      else if (cur.offsetTop + cur.offsetHeight > ol.scrollTop + ol.clientHeight) ol.scrollTop = cur.offsetTop + cur.offsetHeight - ol.clientHeight + 4;
    }
  }
  function listSteps() {
    const ol = $("step-list");
    ol.textContent = "";
    steps.forEach((s, n) => {
      const li = document.createElement("li");
      const no = document.createElement("span"); no.className = "no"; no.textContent = n + "."; no.setAttribute("aria-hidden", "true");
      const b = document.createElement("button"); b.type = "button"; setMarkup(b, tr(s.caption));
      b.addEventListener("click", () => { stepNo = n; showStep(); });
      li.appendChild(no); li.appendChild(b); ol.appendChild(li);
    });
  }
  const stepReplay = (d) => { stepNo = Math.max(0, Math.min(steps.length - 1, stepNo + d)); showStep(); };
  $("step-next").addEventListener("click", () => stepReplay(1));
  $("step-back").addEventListener("click", () => stepReplay(-1));
  $("step-first").addEventListener("click", () => { stepNo = 0; showStep(); });
  $("step-last").addEventListener("click", () => { stepNo = steps.length - 1; showStep(); });

  // -- the turn ---------------------------------------------------------------------------------------------------
  const slider = $("phi");
  slider.max = String(G.phi[N - 1]);
  function show(i) {
    index = i;
    slider.value = String(G.phi[i]);
    slider.setAttribute("aria-valuetext", fx(G.phi[i], 1) + "°");
    $("phi-value").textContent = fill(W().phi, { a: fx(G.phi[i], 1) });
    $("phi-value").setAttribute("data-phi", String(G.phi[i]));
    setMarkup($("s-value"), fill(W().s, { v: fmtG(G.s[i], 4) + (D.rocking ? "°" : " " + unit(sUnit)) }));
    $("theta-value").textContent = fill(W().theta, { a: fx(G.theta[i], 2) });
    $("theta-value").setAttribute("data-value", String(G.theta[i]));
    const k = divisionAt[i];
    $("theta-graphical").textContent = k !== undefined ? fill(W().thetaG, { a: fx(D.divisions[k].theta_g, 1), k: k }) : "";
    document.querySelectorAll("#divisions button").forEach((b) => {
      const on = k !== undefined && b.getAttribute("data-division") === String(k);
      b.className = on ? "current" : ""; b.setAttribute("aria-pressed", on ? "true" : "false");
    });
    drawMech(i); drawPhase(i); moveCursor();
  }
  const stepBy = (d) => show((index + d + N) % N);
  slider.addEventListener("input", () => show(nearest(parseFloat(slider.value))));
  slider.addEventListener("keydown", (ev) => {
    const keys = { ArrowRight: 1, ArrowUp: 1, ArrowLeft: -1, ArrowDown: -1 };
    if (ev.key in keys) { ev.preventDefault(); stepBy(keys[ev.key]); }
    else if (ev.key === "Home") { ev.preventDefault(); show(0); }
    else if (ev.key === "End") { ev.preventDefault(); show(N - 1); }
  });
  $("next").addEventListener("click", () => stepBy(1));
  $("prev").addEventListener("click", () => stepBy(-1));
  function play() {
    if (timer) { clearInterval(timer); timer = null; } else timer = setInterval(() => stepBy(1), 40);
    $("play").textContent = timer ? W().pause : W().play;
    $("play").setAttribute("aria-pressed", timer ? "true" : "false");
  }
  $("play").addEventListener("click", play);
  D.divisions.forEach((d, k) => {
    const b = document.createElement("button");
    b.type = "button"; b.textContent = String(k); b.setAttribute("data-division", String(k));
    b.addEventListener("click", () => show(nearest(d.phi)));
    $("divisions").appendChild(b);
  });
  document.addEventListener("keydown", (ev) => {
    const t = ev.target, tag = t && t.tagName;
    if (ev.altKey || ev.ctrlKey || ev.metaKey) return;
    if (tag === "INPUT" && t.type !== "range") return;
    if (tag === "SELECT" || tag === "TEXTAREA") return;
    if (ev.key === " " || ev.key === "Spacebar") { if (tag === "BUTTON") return; ev.preventDefault(); play(); return; }
    if (t === slider) return;
    const inReplay = t && t.closest && t.closest("#replay-section");
    if (inReplay) {
      if (ev.key === "ArrowRight") { ev.preventDefault(); stepReplay(1); }
      else if (ev.key === "ArrowLeft") { ev.preventDefault(); stepReplay(-1); }
      else if (ev.key === "Home") { ev.preventDefault(); stepNo = 0; showStep(); }
      else if (ev.key === "End") { ev.preventDefault(); stepNo = steps.length - 1; showStep(); }
      return;
    }
    if (ev.key === "ArrowRight") { ev.preventDefault(); stepBy(1); }
    else if (ev.key === "ArrowLeft") { ev.preventDefault(); stepBy(-1); }
  });

  // -- the words --------------------------------------------------------------------------------------------------
  function words() {
    const w = W();
    document.documentElement.lang = lang;
    document.title = tr(D.title) + " — graphplan";
    $("title").textContent = tr(D.title);
    const mm = (x) => fx(x * 1000, 1);
    setMarkup($("facts"), fill(w.facts, {
      f: D.rocking ? fill(w.rocking, { l: mm(D.arm), a: mm(D.centre_distance) }) : fill(w.translating, { e: mm(D.e) }),
      r: D.laws[0], t: D.laws[1], p: D.phases.map((p) => fx(p, 0)).join(" / "), w: fmtG(D.omega, 4),
      R: mm(D.R0), m: fx(D.R0_min * 1000, 2), ar: fx(D.allowed[0], 0), at: fx(D.allowed[1], 0) }));
    document.querySelectorAll("#langs button").forEach((b) => b.setAttribute("aria-pressed", b.getAttribute("data-lang") === lang ? "true" : "false"));
    $("langs").setAttribute("aria-label", w.langs);
    $("play").textContent = timer ? w.pause : w.play;
    $("play").setAttribute("aria-label", w.playName);
    $("prev").setAttribute("aria-label", w.prev);
    $("next").setAttribute("aria-label", w.next);
    slider.setAttribute("aria-label", w.slider);
    $("divisions").setAttribute("aria-label", w.divisions);
    setMarkup($("cap-mech"), fill(w.mech, { mu: fmtG(D.mu_l, 4) }));
    setMarkup($("cap-phase"), D.rocking ? w.phaseRocking : w.phase);
    setMarkup($("cap-diagrams"), w.diagrams);
    [["mech", "cap-mech"], ["phase", "cap-phase"], ["diagrams", "cap-diagrams"], ["replay", "cap-replay"]].forEach(([s, c]) =>
      $(s).setAttribute("aria-label", $(c).textContent + "; " + w.zoomKeys));
    $("zoom-note").textContent = w.zoom;
    $("cap-values").textContent = w.values;
    $("values-note").textContent = fill(w.note, { p: dec(String(D.precision)) });
    $("cap-warnings").textContent = w.warnings;
    $("cap-replay").textContent = w.replay;
    $("step-back").textContent = w.back; $("step-next").textContent = w.forward;
    $("step-back").setAttribute("aria-label", w.backName); $("step-next").setAttribute("aria-label", w.forwardName);
    $("step-first").setAttribute("aria-label", w.first); $("step-last").setAttribute("aria-label", w.last);
    $("footer").textContent = w.footer;
    drawTable();
    listSteps();
  }
  function setLanguage(l) { lang = l; words(); drawDiagrams(); showStep(); show(index); }
  document.querySelectorAll("#langs button").forEach((b) => b.addEventListener("click", () => setLanguage(b.getAttribute("data-lang"))));
  const replayBox = mechBox.slice();       // the inversion: the cam's frame, the pivots' circle (rocking) whole
  if (D.rocking) { const a = D.centre_distance / D.mu_l; grow(replayBox, [-a, -a]); grow(replayBox, [a, a]); }
  D.steps.forEach((s) => { if (s.draw.at) grow(replayBox, s.draw.at); });
  function fitAll() { mechZ.fit(mechBox, 16); phaseZ.fit(phaseBox, 44); replayZ.fit(replayBox, 16); }
  words();
  fitAll();
  drawDiagrams();
  showStep();
  show(0);
  let resizeTimer = null;
  window.addEventListener("resize", () => { clearTimeout(resizeTimer); resizeTimer = setTimeout(() => { fitAll(); drawDiagrams(); showStep(); show(index); }, 60); });
  window.graphplanCam = { show: show, nearest: nearest, phi: G.phi };
})();
