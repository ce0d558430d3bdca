// graphplan explorer: draws the data Python computed (no solver here). Plain ES2017, no library.
"use strict";
(function () {
  const D = JSON.parse(document.getElementById("explorer-data").textContent);
  const NS = "http://www.w3.org/2000/svg";
  const WORDS = {
    en: {
      play: "▶ play", pause: "⏸ pause", phi: "φ", mech: "Mechanism at scale, μl = ",
      vplan: "Velocity plan, μv = ", aplan: "Acceleration plan, μa = ",
      values: "Values at the current angle", q: "quantity", graphical: "graphical", exact: "exact",
      error: "error, %", note: "graphical: read off the plan of a lab position with a ruler of ",
      noteb: " mm (length on the plan, mm → value); exact: the analytic solution; error = 100·(graphical − exact)/exact.",
      warnings: "Warnings here", all: "Over the cycle", replay: "The construction, step by step",
      back: "◀ back", next: "forward ▶", step: "step", of: "of", position: "position",
      velocity: "velocity plan", acceleration: "acceleration plan",
      diagrams: "s–v–a diagrams by chords (dots: graphical; grey: exact; red: the current angle)",
      extreme: "extreme (dead-centre) position of the output: φ = ",
      crossing: ": the direction lines cross at ", small: "° (ill-conditioned plan)",
      none: "none", turn: "crank turn from position 0, °", lab: "lab position ",
      structure: "structure ", omega: "ω1 = ", facts2: " rad/s",
      plansnote: "grey: the exact plan of this angle (vectors from the pole at the plan's scale); black: the graphical plan of a lab position",
      footer: "graphplan explorer: one offline file, no network access; the values are computed by graphplan's exact solver and its graphical constructions.",
      diagnote: "graphical differentiation by chords: ", pole: "pole distances H1 = ", mmw: " mm",
    },
    uk: {
      play: "▶ пуск", pause: "⏸ пауза", phi: "φ", mech: "Механізм у масштабі, μl = ",
      vplan: "План швидкостей, μv = ", aplan: "План прискорень, μa = ",
      values: "Значення при поточному куті", q: "величина", graphical: "графічно", exact: "точно",
      error: "похибка, %", note: "графічно: зміряно на плані лабораторного положення лінійкою з точністю ",
      noteb: " мм (відрізок на плані, мм → значення); точно: аналітичний розв'язок; похибка = 100·(графічно − точно)/точно.",
      warnings: "Попередження тут", all: "За цикл", replay: "Побудова крок за кроком",
      back: "◀ назад", next: "вперед ▶", step: "крок", of: "з", position: "положення",
      velocity: "план швидкостей", acceleration: "план прискорень",
      diagrams: "Діаграми s–v–a методом хорд (точки: графічно; сіре: точно; червоне: поточний кут)",
      extreme: "крайнє (мертве) положення вихідної ланки: φ = ",
      crossing: ": лінії напрямків перетинаються під кутом ", small: "° (план погано обумовлений)",
      none: "немає", turn: "поворот кривошипа від положення 0, °", lab: "положення ",
      structure: "структура ", omega: "ω1 = ", facts2: " рад/с",
      plansnote: "сіре: точний план цього кута (вектори з полюса в масштабі плану); чорне: графічний план лабораторного положення",
      footer: "graphplan explorer: один офлайн-файл, без мережі; значення обчислені точним розв'язувачем graphplan і його графічними побудовами.",
      diagnote: "графічне диференціювання методом хорд: ", pole: "полюсні відстані H1 = ", mmw: " мм",
    },
  };
  const W = WORDS[D.lang] || WORDS.en;
  const UNITS = D.lang === "uk" ? { "m/s": "м/с", "m/s²": "м/с²", "rad/s": "рад/с", "rad/s²": "рад/с²", "m": "м", "rad": "рад" } : {};
  const unit = (u) => UNITS[u] || u;
  const G = D.grid, S = D.scheme, N = G.phi.length;
  const $ = (id) => document.getElementById(id);

  // -- numbers: Python's "{:.4g}" so the page shows what `graphplan analyze` prints ------------------
  // -- numbers as the page's language writes them: the decimal comma in Ukrainian ---------------------
  const dec = (s) => (D.lang === "uk" ? s.replace(/\./g, ",") : s);
  const fx = (x, n) => dec(x.toFixed(n));

  function fmtG(x, p) {
    if (x === null || x === undefined || !isFinite(x)) return "—";
    if (x === 0) return "0";
    const e = x.toExponential(p - 1);
    const exp = parseInt(e.split("e")[1], 10);
    const strip = (s) => (s.indexOf(".") >= 0 ? s.replace(/0+$/, "").replace(/\.$/, "") : s);
    if (exp < -4 || exp >= p) {
      return dec(strip(e.split("e")[0])) + "e" + (exp < 0 ? "-" : "+") + String(Math.abs(exp)).padStart(2, "0");
    }
    const s = strip(x.toFixed(Math.max(0, p - 1 - exp)));
    return s === "-0" ? "0" : dec(s);
  }
  const fmtMu = (v) => fmtG(v, 4);

  // -- svg helpers (drawing mm, y up → screen y down) -----------------------------------------------
  function el(tag, attrs, parent) {
    const n = document.createElementNS(NS, tag);
    for (const k in attrs) n.setAttribute(k, attrs[k]);
    if (parent) parent.appendChild(n);
    return n;
  }
  const r3 = (v) => Math.round(v * 1000) / 1000;
  function line(g, a, b, cls) { return el("line", { x1: r3(a[0]), y1: r3(-a[1]), x2: r3(b[0]), y2: r3(-b[1]), class: cls }, g); }
  function poly(g, pts, cls, closed) {
    return el(closed ? "polygon" : "polyline", { points: pts.map((p) => r3(p[0]) + "," + r3(-p[1])).join(" "), class: cls }, g);
  }
  function arrow(g, a, b, cls) {
    const dx = b[0] - a[0], dy = b[1] - a[1], n = Math.hypot(dx, dy);
    const grp = el("g", { class: cls }, g);
    if (n < 0.3) return grp;
    line(grp, a, b, "");
    const L = Math.min(3, 0.4 * n), H = Math.min(0.6, L / 4), ux = dx / n, uy = dy / n;
    const base = [b[0] - ux * L, b[1] - uy * L];
    poly(grp, [b, [base[0] - uy * H, base[1] + ux * H], [base[0] + uy * H, base[1] - ux * H]], "", true);
    return grp;
  }
  function text(g, at, s, cls, anchor) {
    const t = el("text", { x: r3(at[0]), y: r3(-at[1]), class: cls, "text-anchor": anchor || "start" }, g);
    t.textContent = s;
    return t;
  }
  function fit(svg, box, margin) {
    const [x0, y0, x1, y1] = box;
    const w = x1 - x0 + 2 * margin, h = y1 - y0 + 2 * margin;
    svg.setAttribute("viewBox", [r3(x0 - margin), r3(-y1 - margin), r3(w), r3(h)].join(" "));
    svg.setAttribute("font-size", r3(Math.max(w, h) / 55));   // lettering of about 8 px whatever the scale
  }
  function grow(box, p) { box[0] = Math.min(box[0], p[0]); box[1] = Math.min(box[1], p[1]); box[2] = Math.max(box[2], p[0]); box[3] = Math.max(box[3], p[1]); }
  function clear(svg) { while (svg.firstChild) svg.removeChild(svg.firstChild); }

  // -- the grid ---------------------------------------------------------------------------------------
  const muL = D.scales.mu_l, muV = D.scales.mu_v, muA = D.scales.mu_a;
  function at(name, i) {   // drawing mm of a named point at grid index i
    if (S.frame[name]) return S.frame[name];
    const p = G.points[name];
    return [p.x[i] / muL, p.y[i] / muL];
  }
  const labKey = {};       // grid index → lab position
  D.positions.forEach((p) => {
    let best = 0;
    for (let i = 0; i < N; i++) if (Math.abs(G.phi[i] - p.phi) < Math.abs(G.phi[best] - p.phi)) best = i;
    if (Math.abs(G.phi[best] - p.phi) < 1e-6) labKey[best] = p;
  });
  function nearest(phi) {
    let best = 0, gap = 1e9;
    for (let i = 0; i < N; i++) {
      const d = Math.abs(((G.phi[i] - phi + 540) % 360) - 180);
      if (d < gap - 1e-12) { gap = d; best = i; }
    }
    return best;
  }
  const turnOf = (phi) => ((((phi - D.phi0) * Math.sign(D.omega1)) % 360) + 360) % 360;

  // -- the mechanism -----------------------------------------------------------------------------------
  const mech = $("mech");
  const mechBox = [1e9, 1e9, -1e9, -1e9];
  Object.values(S.frame).forEach((p) => grow(mechBox, p));
  Object.keys(G.points).forEach((n) => { for (let i = 0; i < N; i++) grow(mechBox, at(n, i)); });
  fit(mech, mechBox, 14);
  const mechStatic = el("g", {}, mech), mechMoving = el("g", {}, mech);
  (function drawStatic() {
    S.guides.forEach((g) => {
      const u = [Math.cos(g.angle * Math.PI / 180), Math.sin(g.angle * Math.PI / 180)];
      let lo = 1e9, hi = -1e9;
      for (let i = 0; i < N; i++) {
        const p = at(g.point, i), t = (p[0] - g.through[0]) * u[0] + (p[1] - g.through[1]) * u[1];
        lo = Math.min(lo, t); hi = Math.max(hi, t);
      }
      line(mechStatic, [g.through[0] + (lo - 12) * u[0], g.through[1] + (lo - 12) * u[1]],
        [g.through[0] + (hi + 12) * u[0], g.through[1] + (hi + 12) * u[1]], "guide");
    });
    S.trajectories.forEach((n) => {
      const order = G.phi.map((_, i) => i).sort((a, b) => turnOf(G.phi[a]) - turnOf(G.phi[b]));
      poly(mechStatic, order.map((i) => at(n, i)), "traj", true);
    });
    D.positions.forEach((p) => {
      const i = nearest(p.phi), A = at(S.crank.pin, i), O = S.frame[S.crank.pivot];
      const d = Math.hypot(A[0] - O[0], A[1] - O[1]) || 1;
      el("circle", { cx: r3(A[0]), cy: r3(-A[1]), r: 0.6, class: "labpos" }, mechStatic);
      if (p.index !== null) text(mechStatic, [A[0] + (A[0] - O[0]) / d * 5 - 1.2, A[1] + (A[1] - O[1]) / d * 5 - 1.2], String(p.index), "lbl scale");
    });
    S.pivots.forEach((n) => {
      const p = S.frame[n];
      poly(mechStatic, [p, [p[0] - 3, p[1] - 5], [p[0] + 3, p[1] - 5]], "ground", true);
      line(mechStatic, [p[0] - 5, p[1] - 5], [p[0] + 5, p[1] - 5], "ground");
      for (let k = -4; k <= 4; k += 2) line(mechStatic, [p[0] + k, p[1] - 5], [p[0] + k - 1.5, p[1] - 6.5], "ground");
    });
  })();
  function drawMechanism(i) {
    clear(mechMoving);
    S.links.forEach((L) => {
      const pts = L.joints.map((j) => at(j, i));
      if (L.slot.length && pts.length >= 2) {
        const a = pts[0], b = pts[pts.length - 1], n = Math.hypot(b[0] - a[0], b[1] - a[1]);
        const u = [(b[0] - a[0]) / n, (b[1] - a[1]) / n];
        let lo = 0, hi = n;
        L.slot.forEach((s) => { const p = at(s, i), t = (p[0] - a[0]) * u[0] + (p[1] - a[1]) * u[1]; lo = Math.min(lo, t - 6); hi = Math.max(hi, t + 6); });
        line(mechMoving, [a[0] + lo * u[0], a[1] + lo * u[1]], [a[0] + hi * u[0], a[1] + hi * u[1]], "link");
      }
      if (pts.length >= 2) poly(mechMoving, pts, "link", pts.length > 2);
      if (L.block) {
        const c = at(L.block, i), th = G.links[L.name].theta[i] * Math.PI / 180;
        const u = [Math.cos(th), Math.sin(th)], v = [-u[1], u[0]];
        const corner = (sx, sy) => [c[0] + u[0] * sx * 4.5 + v[0] * sy * 2.5, c[1] + u[1] * sx * 4.5 + v[1] * sy * 2.5];
        poly(mechMoving, [corner(-1, -1), corner(1, -1), corner(1, 1), corner(-1, 1)], "block", true);
      }
    });
    const seen = {};
    S.links.forEach((L) => L.joints.forEach((j) => {
      if (seen[j]) return;
      seen[j] = 1;
      const p = at(j, i);
      el("circle", { cx: r3(p[0]), cy: r3(-p[1]), r: 0.9, class: "joint" }, mechMoving);
      text(mechMoving, [p[0] + 1.6, p[1] + 1.6], j, "lbl");
    }));
    Object.keys(G.points).forEach((n) => {
      if (seen[n] || !/^S/.test(n)) return;
      const p = at(n, i);
      el("circle", { cx: r3(p[0]), cy: r3(-p[1]), r: 0.5, class: "labpos" }, mechMoving);
      text(mechMoving, [p[0] + 1.2, p[1] - 3.5], n, "lbl");
    });
  }

  // -- the plans of the current angle ---------------------------------------------------------------
  const recByKey = { velocity: {}, acceleration: {} };
  D.records.forEach((r) => { recByKey[r.kind][r.key] = r; });
  function planVector(kind, name, i) {
    const p = G.points[name], mu = kind === "velocity" ? muV : muA;
    return kind === "velocity" ? [p.vx[i] / mu, p.vy[i] / mu] : [p.ax[i] / mu, p.ay[i] / mu];
  }
  function imageOf(kind, name, i) { return S.frame[name] ? [0, 0] : planVector(kind, name, i); }
  function recordBox(r, box) {
    r.items.forEach((it) => { for (let k = 0; k < it[1].length; k += 2) grow(box, [it[1][k], it[1][k + 1]]); });
  }
  function drawRecord(g, r, upto, current) {   // upto: the last step shown (all when undefined)
    const stepOf = {};
    if (upto !== undefined) r.steps.forEach((s, k) => s.items.forEach((j) => { stepOf[j] = k; }));
    r.items.forEach((it, j) => {
      const [kind, f, role, radius] = it;
      let s = upto === undefined ? -1 : stepOf[j];
      if (kind === "text") s = upto === undefined ? -1 : r.labels[String(j)];
      if (upto !== undefined && role !== "pole" && (s === undefined || s > upto)) return;
      const hl = upto !== undefined && s === current && kind !== "text" ? " hl" : "";
      const pts = [];
      for (let k = 0; k < f.length; k += 2) pts.push([f[k], f[k + 1]]);
      if (kind === "vector") arrow(g, pts[0], pts[1], "g-vec" + hl);
      else if (kind === "segment") line(g, pts[0], pts[1], (role === "direction" || role === "construction" ? "g-line" : "g-vec") + hl);
      else if (kind === "point") el("circle", { cx: r3(pts[0][0]), cy: r3(-pts[0][1]), r: 0.6, class: "g-vec" }, g);
      else if (kind === "circle") el("circle", { cx: r3(pts[0][0]), cy: r3(-pts[0][1]), r: radius, class: "g-line" + hl }, g);
      else if (kind === "polyline" || kind === "polygon") poly(g, pts, "g-line" + hl, kind === "polygon");
      else if (kind === "text") text(g, [pts[0][0], pts[0][1]], it[6], "lbl g-text");
    });
  }
  function planBox(kind) {
    const box = [0, 0, 0, 0];
    Object.keys(G.points).forEach((n) => { for (let i = 0; i < N; i++) grow(box, planVector(kind, n, i)); });
    Object.values(recByKey[kind]).forEach((r) => recordBox(r, box));
    return box;
  }
  const planSvg = { velocity: $("vplan"), acceleration: $("aplan") };
  ["velocity", "acceleration"].forEach((k) => fit(planSvg[k], planBox(k), 10));
  function drawPlan(kind, i) {
    const svg = planSvg[kind];
    clear(svg);
    const g = el("g", {}, svg);
    S.links.forEach((L) => {
      if (L.name === S.crank.link || L.joints.length < 2) return;
      poly(g, L.joints.map((j) => imageOf(kind, j, i)), "figure", L.joints.length > 2);
    });
    Object.keys(G.points).forEach((n) => {
      const p = planVector(kind, n, i);
      arrow(g, [0, 0], p, "exact");
    });
    const lab = labKey[i];
    if (!(lab && recByKey[kind][lab.key])) {    // a lab position's plan brings its own labels
      Object.keys(G.points).forEach((n) => { const p = planVector(kind, n, i); text(g, [p[0] + 1, p[1] + 1], n.toLowerCase(), "lbl exact"); });
      text(g, [-4, -5], kind === "velocity" ? "p_v" : "π", "lbl");
    }
    if (lab && recByKey[kind][lab.key]) drawRecord(el("g", {}, svg), recByKey[kind][lab.key]);
  }

  // -- the values' table --------------------------------------------------------------------------------
  const SYM = { omega: "ω_", epsilon: "ε_", slide_v: D.lang === "uk" ? "v_відн " : "v_rel ", slide_k: "a^k " };
  function label(row) {
    if (row.source === "point") return (row.plan === "velocity" ? "v_" : "a_") + row.name;
    return SYM[row.source] + row.name;
  }
  function exactValue(row, i) {
    if (row.source === "point") {
      const p = G.points[row.name];
      return row.plan === "velocity" ? Math.hypot(p.vx[i], p.vy[i]) : Math.hypot(p.ax[i], p.ay[i]);
    }
    if (row.source === "omega") return G.links[row.name].omega[i];
    if (row.source === "epsilon") return G.links[row.name].epsilon[i];
    if (row.source === "slide_v") return G.slides[row.name].v[i];
    return G.slides[row.name].k[i];
  }
  const tbody = $("values").querySelector("tbody");
  $("values").querySelector("thead").innerHTML = "<tr><th>" + W.q + "</th><th>" + W.graphical + "</th><th>" + W.exact + "</th><th>" + W.error + "</th></tr>";
  const cells = D.rows.map((row) => {
    const tr = document.createElement("tr");
    tr.setAttribute("data-q", row.q);
    tr.setAttribute("data-plan", row.plan);
    const th = document.createElement("th");
    th.textContent = label(row) + ", " + unit(row.unit);
    tr.appendChild(th);
    const td = ["graphical", "exact", "error"].map((c) => { const t = document.createElement("td"); t.className = c; tr.appendChild(t); return t; });
    tbody.appendChild(tr);
    return [row, tr, td];
  });
  function updateTable(i) {
    const lab = labKey[i], got = lab ? D.readings[String(lab.key)] || {} : {};
    cells.forEach(([row, tr, td]) => {
      const x = exactValue(row, i), r = got[row.q];
      td[1].textContent = fmtG(x, 4);
      td[1].setAttribute("data-value", String(x));
      if (r) {
        const g = row.source === "slide_v" && x < 0 ? -r[1] : r[1];   // signed along the guide, as exact
        td[0].textContent = fmtG(g, 4) + (r[0] !== null ? " (" + fx(r[0], 1) + (D.lang === "uk" ? " мм)" : " mm)") : "");
        td[0].setAttribute("data-value", String(g));
        td[2].textContent = r[2] === null ? "—" : fx(r[2], 2);
        td[2].className = "error" + (r[2] !== null && Math.abs(r[2]) > 5 ? " bad" : "");
      } else {
        td[0].textContent = "";
        td[0].removeAttribute("data-value");
        td[2].textContent = "";
      }
    });
  }

  // -- warnings ----------------------------------------------------------------------------------------
  function updateWarnings(i) {
    const ul = $("warnings");
    ul.innerHTML = "";
    const add = (kind, s) => { const li = document.createElement("li"); li.setAttribute("data-kind", kind); li.textContent = s; ul.appendChild(li); };
    const half = D.step / 2 + 1e-6;
    D.warnings.extremes.forEach((e) => { if (Math.abs(((G.phi[i] - e + 540) % 360) - 180) <= half) add("extreme", W.extreme + fx(e, 2) + "°"); });
    Object.keys(G.crossing).forEach((g) => { const a = G.crossing[g][i]; if (a < D.warnings.small) add("crossing", g + W.crossing + fx(a, 1) + W.small); });
    const lab = labKey[i];
    if (lab && D.warnings.plans[String(lab.key)]) D.warnings.plans[String(lab.key)].forEach((s) => add("plan", s));
    if (!ul.firstChild) add("none", W.none);
  }
  (function allWarnings() {
    const ul = $("warnings-all");
    const add = (s) => { const li = document.createElement("li"); li.textContent = s; ul.appendChild(li); };
    D.warnings.extremes.forEach((e) => add(W.extreme + fx(e, 2) + "°"));
    Object.keys(G.crossing).forEach((g) => {
      let lo = 90, where = 0;
      G.crossing[g].forEach((a, i) => { if (a < lo) { lo = a; where = G.phi[i]; } });
      if (lo < D.warnings.small) add(g + W.crossing + fx(lo, 1) + W.small + ", φ = " + fx(where, 1) + "°");
    });
    Object.keys(D.warnings.plans).forEach((k) => D.warnings.plans[k].forEach((s) => add(W.lab + k + ": " + s)));
    D.warnings.study.forEach(add);
  })();

  // -- the s–v–a diagrams ---------------------------------------------------------------------------------
  const dg = D.diagrams, dsvg = $("diagrams");
  const CH = 48, GAP = 14, WIDTH = 240;
  let cursor = null;
  (function drawDiagrams() {
    if (!dg) return;
    dsvg.setAttribute("viewBox", [-28, -6, WIDTH + 40, 3 * (CH + GAP) + 10].join(" "));
    const order = G.phi.map((_, i) => i).sort((a, b) => turnOf(G.phi[a]) - turnOf(G.phi[b]));
    ["s", "v", "a"].forEach((key, row) => {
      const y0 = row * (CH + GAP);
      const ex = dg.exact[key], ch = dg.chords[key];
      let lo = Math.min(0, ...ex, ...ch.map((c) => c[1])), hi = Math.max(0, ...ex, ...ch.map((c) => c[1]));
      if (hi - lo < 1e-12) hi = lo + 1;
      const X = (turn) => (turn / 360) * WIDTH, Y = (v) => y0 + CH - ((v - lo) / (hi - lo)) * CH;
      const g = document.createElementNS(NS, "g");
      dsvg.appendChild(g);
      const ln = (x1, y1, x2, y2, cls) => el("line", { x1: r3(x1), y1: r3(y1), x2: r3(x2), y2: r3(y2), class: cls }, g);
      ln(0, y0, 0, y0 + CH, "axis");
      ln(0, Y(0), WIDTH, Y(0), "axis");
      for (let t = 30; t <= 360; t += 30) ln(X(t), y0, X(t), y0 + CH, "grid");
      el("polyline", { points: order.map((i) => r3(X(turnOf(G.phi[i]))) + "," + r3(Y(ex[i]))).join(" "), class: "curve" }, g);
      ch.forEach((c) => el("circle", { cx: r3(X(turnOf(c[0]))), cy: r3(Y(c[1])), r: 0.8, class: "chord" }, g));
      const sym = dg.symbols[row] + "_" + dg.sub;
      const u = { s: dg.unit, v: dg.unit + "/s", a: dg.unit + "/s²" }[key];
      const t1 = el("text", { x: -26, y: y0 + 4, class: "scale" }, g); t1.textContent = sym + ", " + unit(u);
      const t2 = el("text", { x: -26, y: y0 + 9, class: "scale" }, g); t2.textContent = fmtG(hi, 3);
      const t3 = el("text", { x: -26, y: y0 + CH, class: "scale" }, g); t3.textContent = fmtG(lo, 3);
    });
    const t = el("text", { x: WIDTH / 2, y: 3 * (CH + GAP) + 2, class: "scale", "text-anchor": "middle" }, dsvg);
    t.textContent = W.turn;
    cursor = el("line", { x1: 0, y1: -2, x2: 0, y2: 3 * (CH + GAP) - GAP + 2, class: "cursor", id: "diagram-cursor" }, dsvg);
    $("diagrams-note").textContent = W.diagnote + dg.divisions + " × " + fmtG(360 / dg.divisions, 4) + "°, L = " + dg.L + W.mmw +
      "; " + W.pole + dg.H1 + W.mmw + ", H2 = " + dg.H2 + W.mmw + "; μs = " + fmtMu(dg.mu.s) + ", μt = " + fmtMu(dg.mu.t) +
      ", μv = " + fmtMu(dg.mu.v) + ", μa = " + fmtMu(dg.mu.a);
  })();

  // -- the replay -----------------------------------------------------------------------------------------
  const sel = $("replay-plan"), rsvg = $("replay");
  let current = null, stepNo = 0;
  D.records.forEach((r, k) => {
    const o = document.createElement("option");
    o.value = String(k);
    o.textContent = W[r.kind] + ", " + (r.index !== null ? W.position + " " + r.index : "φ = " + r.phi + "°");
    sel.appendChild(o);
  });
  const firstAccel = D.records.findIndex((r) => r.kind === "acceleration");
  function choose(k) {
    current = D.records[k];
    sel.value = String(k);
    stepNo = 0;
    const box = [0, 0, 0, 0];
    recordBox(current, box);
    fit(rsvg, box, 8);
    const ol = $("step-list");
    ol.innerHTML = "";
    current.steps.forEach((s, n) => { const li = document.createElement("li"); li.setAttribute("data-step", String(n)); li.textContent = s.caption; ol.appendChild(li); });
    showStep();
  }
  function showStep() {
    clear(rsvg);
    drawRecord(el("g", {}, rsvg), current, stepNo, stepNo);
    const s = current.steps[stepNo];
    $("step-caption").textContent = s.caption;
    $("step-eq").textContent = s.eq;
    $("step-count").textContent = W.step + " " + (stepNo + 1) + " " + W.of + " " + current.steps.length;
    $("step-count").setAttribute("data-step", String(stepNo));
    document.querySelectorAll("#step-list li").forEach((li, n) => { li.className = n < stepNo ? "done" : n === stepNo ? "current" : "todo"; });
  }
  sel.addEventListener("change", () => choose(parseInt(sel.value, 10)));
  $("step-next").addEventListener("click", () => { if (stepNo < current.steps.length - 1) { stepNo++; showStep(); } });
  $("step-back").addEventListener("click", () => { if (stepNo > 0) { stepNo--; showStep(); } });
  $("step-first").addEventListener("click", () => { stepNo = 0; showStep(); });
  $("step-last").addEventListener("click", () => { stepNo = current.steps.length - 1; showStep(); });

  // -- the angle ----------------------------------------------------------------------------------------
  const slider = $("phi");
  let index = nearest(D.phi0), timer = null;
  function show(i) {
    index = i;
    slider.value = String(G.phi[i]);
    slider.setAttribute("data-index", String(i));
    const lab = labKey[i];
    $("phi-value").textContent = W.phi + " = " + fx(G.phi[i], 2) + "°" + (lab && lab.index !== null ? " — " + W.lab + lab.index : "");
    $("phi-value").setAttribute("data-phi", String(G.phi[i]));
    document.querySelectorAll("#lab-positions button").forEach((b) => { b.className = lab && b.getAttribute("data-key") === String(lab.key) ? "current" : ""; });
    drawMechanism(i);
    drawPlan("velocity", i);
    drawPlan("acceleration", i);
    updateTable(i);
    updateWarnings(i);
    if (cursor) { const x = r3((turnOf(G.phi[i]) / 360) * WIDTH); cursor.setAttribute("x1", x); cursor.setAttribute("x2", x); }
  }
  slider.addEventListener("input", () => show(nearest(parseFloat(slider.value))));
  slider.addEventListener("change", () => show(nearest(parseFloat(slider.value))));
  const dir = D.omega1 >= 0 ? 1 : -1;
  $("next").addEventListener("click", () => show((index + dir + N) % N));
  $("prev").addEventListener("click", () => show((index - dir + N) % N));
  $("play").addEventListener("click", () => {
    if (timer) { clearInterval(timer); timer = null; $("play").textContent = W.play; return; }
    $("play").textContent = W.pause;
    timer = setInterval(() => show((index + dir + N) % N), 40);
  });
  D.positions.forEach((p) => {
    const b = document.createElement("button");
    b.type = "button";
    b.setAttribute("data-key", String(p.key));
    b.textContent = p.index !== null ? String(p.index) : fx(p.phi, 1) + "°";
    b.title = W.lab + (p.index !== null ? p.index : "") + ", φ = " + fx(p.phi, 2) + "°";
    b.addEventListener("click", () => show(nearest(p.phi)));
    $("lab-positions").appendChild(b);
  });

  // -- the words ---------------------------------------------------------------------------------------
  $("facts").textContent = W.structure + D.structure + "; " + W.omega + fmtG(D.omega1, 5) + W.facts2 + "; φ0 = " + fx(D.phi0, 2) + "°";
  $("play").textContent = W.play;
  $("cap-mech").textContent = W.mech + fmtMu(muL) + (D.lang === "uk" ? " м/мм" : " m/mm");
  $("cap-vplan").textContent = W.vplan + fmtMu(muV) + (D.lang === "uk" ? " (м/с)/мм" : " (m/s)/mm");
  $("cap-aplan").textContent = W.aplan + fmtMu(muA) + (D.lang === "uk" ? " (м/с²)/мм" : " (m/s²)/mm");
  $("cap-values").textContent = W.values;
  $("values-note").textContent = W.note + D.precision + W.noteb + " " + W.plansnote + ".";
  $("cap-warnings").textContent = W.warnings;
  $("cap-replay").textContent = W.replay;
  $("cap-diagrams").textContent = W.diagrams;
  $("step-back").textContent = W.back;
  $("step-next").textContent = W.next;
  $("footer").textContent = W.footer;
  choose(firstAccel >= 0 ? firstAccel : 0);
  show(index);
  window.graphplanExplorer = { show: show, nearest: nearest, phi: G.phi };
})();
