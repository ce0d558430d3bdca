// graphplan explorer: draws the data Python computed (no solver here). Plain ES2017, no library.
"use strict";
(function () {
  const D = JSON.parse(document.getElementById("explorer-data").textContent);
  const NS = "http://www.w3.org/2000/svg";
  const $ = (id) => document.getElementById(id);
  const WORDS = {
    en: {
      play: "▶ play", pause: "⏸ pause", playName: "play or pause the turn (Space)", speed: "speed",
      prev: "one grid step back (←)", next: "one grid step forward (→)", slider: "crank turn from position 0",
      turn: "turn from position 0", phi: "crank angle φ", lab: "position", labs: "lab positions",
      mech: "Mechanism, μ_l = ", vplan: "Velocity plan, μ_v = ", aplan: "Acceleration plan, μ_a = ", ofAngle: " (the scale of this angle)",
      zoomKeys: "keys: + and − zoom, the arrows move, 0 shows the whole drawing",
      perAngle: "plans at a scale of their own for each angle (on paper one scale serves the turn)",
      zoom: "Wheel or pinch to zoom a drawing, drag to move it, double-click to fit it again; on a focused drawing (Tab) + and − zoom, "
        + "the arrows move it, 0 fits it; on the diagrams ← → seek the angle.",
      values: "Values at the current angle", q: "quantity", graphical: "graphical", exact: "exact", error: "error, %",
      note: "graphical: read off the plan of a lab position with a ruler of {p} mm (length on the plan, mm → value); "
        + "exact: the analytic solution; error = 100·(graphical − exact)/exact. Grey: the exact plan of this angle; "
        + "black: the graphical plan of a lab position.",
      warnings: "Warnings here", all: "Over the cycle", none: "none",
      extreme: "extreme (dead-centre) position of the output: φ = {a}°",
      crossing: "{g}: the direction lines cross at {a}° (ill-conditioned plan)",
      replay: "The construction, step by step", back: "◀ back", forward: "forward ▶", first: "first step (Home)",
      last: "last step (End)", backName: "one step back (←)", forwardName: "one step forward (→)",
      step: "step {k} of {n}", plan: "plan to replay", returnTo: "↩ back to φ = {a}°",
      rmech: "The mechanism at the plan's position, φ = {a}°: the link of the step in red, its direction line dashed",
      eqKey: "  (═ known in size and direction; ─ in direction only)",
      velocity: "velocity plan", acceleration: "acceleration plan", at: "position {k}",
      legend: "Symbols", check: "Check your own plan",
      checkNote: "Type the lengths you measured on your own plan of this position, mm: the page multiplies them by "
        + "the scale and compares the value with the exact one, as the lab's table does (δ = 100·(value − exact)/exact).",
      checkAt: "position", reveal: "show graphplan's own reading", yourMm: "your length, mm", value: "value",
      theirs: "graphplan: mm, δ %", mu: "μ",
      diagrams: "s–v–a diagrams by chords (dots: graphical; grey: exact; red: the current angle; click or drag to seek)",
      diagnote: "graphical differentiation by chords: {n} × {d}°, L = {L} mm; pole distances H_1 = {H1} mm, H_2 = {H2} mm; "
        + "μ_s = {ms}, μ_t = {mt}, μ_v = {mv}, μ_a = {ma}",
      turnAxis: "crank turn from position 0, °",
      structure: "structure ", facts: "; ω_1 = {w} rad/s; φ_0 = {p}°",
      footer: "graphplan explorer: one offline file, no network access; the values are computed by graphplan's exact "
        + "solver and its graphical constructions.",
      langs: "language",
      openAccel: "The page opened at {at}, where the sheet draws the acceleration plan{still}. The button 0 returns to position 0.",
      openStill: "The page opened at {at}{still}. The button 0 returns to position 0.",
      still0: " (position 0 is an extreme position: the output stands still there and most velocities are zero)",
      atPosition: "position {k}",
      symbols: [["p_v, π", "the poles of the velocity and acceleration plans"], ["μ_l, μ_v, μ_a", "the scales: m, m/s, m/s² per mm"],
        ["a^n_{BA}", "normal acceleration of B about A, v^2_{BA}/l_{BA}, toward A"],
        ["a^τ_{BA}", "tangential acceleration of B about A, ⊥ BA"], ["a^k", "Coriolis acceleration 2·ω·v_r"],
        ["a^r, v^r", "relative acceleration and velocity along a guide"], ["n_1, k_1", "the ends of laid-off normal and Coriolis components"],
        ["ω, ε", "angular velocity and acceleration, + counter-clockwise"]],
    },
    uk: {
      play: "▶ пуск", pause: "⏸ пауза", playName: "пуск або пауза обертання (пробіл)", speed: "швидкість",
      prev: "на крок сітки назад (←)", next: "на крок сітки вперед (→)", slider: "поворот кривошипа від положення 0",
      turn: "поворот від положення 0", phi: "кут кривошипа φ", lab: "положення", labs: "лабораторні положення",
      mech: "Механізм, μ_l = ", vplan: "План швидкостей, μ_v = ", aplan: "План прискорень, μ_a = ", ofAngle: " (масштаб цього кута)",
      zoomKeys: "клавіші: + і − масштаб, стрілки зсувають, 0 показує все креслення",
      perAngle: "плани у власному масштабі для кожного кута (на папері — один масштаб на оберт)",
      zoom: "Коліщатко або жест — масштаб креслення, перетягування — зсув, подвійне клацання — повернути; на вибраному (Tab) "
        + "кресленні + і − — масштаб, стрілки — зсув, 0 — усе креслення; на діаграмах ← → — кут.",
      values: "Значення при поточному куті", q: "величина", graphical: "графічно", exact: "точно", error: "похибка, %",
      note: "графічно: зміряно на плані лабораторного положення лінійкою з точністю {p} мм (відрізок на плані, мм → "
        + "значення); точно: аналітичний розв'язок; похибка = 100·(графічно − точно)/точно. Сіре — точний план цього "
        + "кута; чорне — графічний план лабораторного положення.",
      warnings: "Попередження тут", all: "За цикл", none: "немає",
      extreme: "крайнє (мертве) положення вихідної ланки: φ = {a}°",
      crossing: "{g}: лінії напрямків перетинаються під кутом {a}° (план погано обумовлений)",
      replay: "Побудова крок за кроком", back: "◀ назад", forward: "вперед ▶", first: "перший крок (Home)",
      last: "останній крок (End)", backName: "на крок назад (←)", forwardName: "на крок вперед (→)",
      step: "крок {k} з {n}", plan: "план для показу", returnTo: "↩ назад до φ = {a}°",
      rmech: "Механізм у положенні плану, φ = {a}°: ланка кроку червона, її лінія напрямку штрихова",
      eqKey: "  (═ відомий за величиною і напрямом; ─ лише за напрямом)",
      velocity: "план швидкостей", acceleration: "план прискорень", at: "положення {k}",
      legend: "Позначення", check: "Перевірте свій план",
      checkNote: "Введіть довжини, зміряні на власному плані цього положення, мм: сторінка помножить їх на масштаб і "
        + "порівняє значення з точним, як у лабораторній таблиці (δ = 100·(значення − точно)/точно).",
      checkAt: "положення", reveal: "показати відліки graphplan", yourMm: "ваш відрізок, мм", value: "значення",
      theirs: "graphplan: мм, δ %", mu: "μ",
      diagrams: "Діаграми s–v–a методом хорд (точки: графічно; сіре: точно; червоне: поточний кут; клацніть або "
        + "тягніть, щоб перейти)",
      diagnote: "графічне диференціювання методом хорд: {n} × {d}°, L = {L} мм; полюсні відстані H_1 = {H1} мм, "
        + "H_2 = {H2} мм; μ_s = {ms}, μ_t = {mt}, μ_v = {mv}, μ_a = {ma}",
      turnAxis: "поворот кривошипа від положення 0, °",
      structure: "структура ", facts: "; ω_1 = {w} рад/с; φ_0 = {p}°",
      footer: "graphplan explorer: один офлайн-файл, без мережі; значення обчислені точним розв'язувачем graphplan і "
        + "його графічними побудовами.",
      langs: "мова",
      openAccel: "Сторінка відкрилася в {at}, для якого аркуш будує план прискорень{still}. Кнопка 0 повертає в положення 0.",
      openStill: "Сторінка відкрилася в {at}{still}. Кнопка 0 повертає в положення 0.",
      still0: " (положення 0 крайнє: вихідна ланка в ньому стоїть, і більшість швидкостей нульові)",
      atPosition: "положенні {k}",
      symbols: [["p_v, π", "полюси плану швидкостей і плану прискорень"], ["μ_l, μ_v, μ_a", "масштаби: м, м/с, м/с² в 1 мм"],
        ["a^n_{BA}", "нормальне прискорення B відносно A, v^2_{BA}/l_{BA}, до A"],
        ["a^τ_{BA}", "тангенціальне прискорення B відносно A, ⊥ BA"], ["a^k", "прискорення Коріоліса 2·ω·v_r"],
        ["a^r, v^r", "відносні прискорення і швидкість уздовж напрямної"], ["n_1, k_1", "кінці відкладених нормальних і коріолісових складових"],
        ["ω, ε", "кутові швидкість і прискорення, + проти годинникової стрілки"]],
    },
  };
  const UNITS = { uk: { "m/s": "м/с", "m/s²": "м/с²", "rad/s": "рад/с", "rad/s²": "рад/с²", "m": "м", "rad": "рад", "mm": "мм",
    "m/mm": "м/мм", "(m/s)/mm": "(м/с)/мм", "(m/s²)/mm": "(м/с²)/мм", "s/mm": "с/мм" }, en: {} };
  let lang = D.lang === "en" ? "en" : "uk";
  const W = () => WORDS[lang];
  const unit = (u) => UNITS[lang][u] || u;
  const fill = (s, f) => s.replace(/\{(\w+)\}/g, (m, k) => (k in f ? f[k] : m));
  const tr = (v) => (v && typeof v === "object" ? (v[lang] !== undefined ? v[lang] : v.en) : v);

  // -- the lab's markup (graphplan.util.markup): a^τ_{CB}, p_v, M^*_с ---------------------------------
  const wordChar = (c) => /[\p{L}\p{N}'′]/u.test(c);
  function runs(text) {
    const out = [], base = [];
    let i = 0;
    const n = text.length;
    const flush = () => { if (base.length) { out.push({ text: minus(base.join("")), level: 0, stacked: false }); base.length = 0; } };
    while (i < n) {
      const c = text[i];
      if (c === "\\" && i + 1 < n && "_^{}\\".indexOf(text[i + 1]) >= 0) { base.push(text[i + 1]); i += 2; continue; }
      if ((c === "_" || c === "^") && i + 1 < n) {
        let body;
        if (text[i + 1] === "{") {
          const end = text.indexOf("}", i + 2);
          if (end < 0) { base.push(c); i += 1; continue; }
          body = text.slice(i + 2, end); i = end + 1;
        } else if (text[i + 1] === "*") { body = "*"; i += 2; } else if (wordChar(text[i + 1])) {
          let j = i + 1;
          while (j < n && wordChar(text[j])) j++;
          body = text.slice(i + 1, j); i = j;
        } else { base.push(c); i += 1; continue; }
        flush();
        const level = c === "_" ? -1 : 1, prev = out[out.length - 1];
        out.push({ text: body, level: level, stacked: !!prev && prev.level === -level && !prev.stacked });
        continue;
      }
      base.push(c); i += 1;
    }
    flush();
    return out;
  }
  function setMarkup(node, text) {          // HTML: <sub>, <sup>
    node.textContent = "";
    runs(String(text)).forEach((r) => {
      if (!r.level) { node.appendChild(document.createTextNode(r.text)); return; }
      const e = document.createElement(r.level < 0 ? "sub" : "sup");
      e.textContent = r.text;
      node.appendChild(e);
    });
    return node;
  }
  function svgMarkup(t, text, size) {       // SVG: tspans with shifted baselines, stacked scripts moved back
    let shift = 0, prev = null;
    runs(String(text)).forEach((r) => {
      const ts = document.createElementNS(NS, "tspan");
      const want = r.level < 0 ? 0.3 * size : r.level > 0 ? -0.45 * size : 0;
      if (want !== shift) ts.setAttribute("dy", r3(want - shift));
      shift = want;
      if (r.level) ts.setAttribute("font-size", r3(SCRIPT * size));
      if (r.stacked && prev) {
        const w = prev.getComputedTextLength ? prev.getComputedTextLength() : 0;
        if (w > 0) ts.setAttribute("dx", r3(-w));
      }
      ts.textContent = r.text;
      t.appendChild(ts);
      prev = ts;
    });
  }

  // -- numbers as the page's language writes them: Python's "{:.4g}", the decimal comma in Ukrainian --
  const dec = (s) => (lang === "uk" ? s.replace(/\./g, ",") : s);
  const fx = (x, n) => { const s = x.toFixed(n); return dec(/^-[0.]*$/.test(s) ? s.slice(1) : s).replace(/^-/, "−"); };
  const minus = (s) => String(s).replace(/(^|[^\p{L}\p{N}_])-(?=[\d.,])/gu, "$1−");   // one minus sign: U+2212
  function fmtG(x, p) {                      // p significant digits, never in e-notation
    if (x === null || x === undefined || !isFinite(x)) return "—";
    if (Math.abs(x) < 1e-9) return "0";     // round-off of a vanishing quantity, as the values' table
    const y = Number(x.toPrecision(p));
    const exp = Math.floor(Math.log10(Math.abs(y)));
    let s = y.toFixed(Math.max(0, Math.min(60, p - 1 - exp)));
    if (s.indexOf(".") >= 0) s = s.replace(/0+$/, "").replace(/\.$/, "");
    return s === "-0" ? "0" : minus(dec(s));
  }

  // -- svg helpers (drawing mm, y up → screen y down) -------------------------------------------------
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
  function arrow(g, a, b, cls, px) {          // px: drawing units per screen pixel (the head is 11 px long)
    const dx = b[0] - a[0], dy = b[1] - a[1], n = Math.hypot(dx, dy);
    const grp = el("g", { class: cls }, g);
    if (n < 0.3) return grp;
    line(grp, a, b, "");
    const L = Math.min(11 * px, 0.45 * n), H = L / 3.4, ux = dx / n, uy = dy / n;
    const base = [b[0] - ux * L, b[1] - uy * L];
    poly(grp, [b, [base[0] - uy * H, base[1] + ux * H], [base[0] + uy * H, base[1] - ux * H]], "", true);
    return grp;
  }
  function clear(svg) { while (svg.firstChild) svg.removeChild(svg.firstChild); }
  function grow(box, p) { box[0] = Math.min(box[0], p[0]); box[1] = Math.min(box[1], p[1]); box[2] = Math.max(box[2], p[0]); box[3] = Math.max(box[3], p[1]); }

  // -- drawings that zoom and pan, lettered at a constant size on the screen ------------------------------
  const LETTER = 14;     // px: the drawings' lettering (11–16 px at every width, as the text beside them)
  const SCRIPT = 0.8;    // sub- and superscripts: 0.8 of the letter (11.2 px)
  const SERIES = [1, 2, 2.5, 4, 5];
  function standardAtLeast(v) {              // the smallest 1, 2, 2.5, 4, 5 × 10^k ≥ v (graphic.scales.at_least)
    const k0 = Math.floor(Math.log10(v));
    for (let k = k0 - 1; k <= k0 + 1; k++) for (const m of SERIES) { const c = Number(m + "e" + k); if (c >= v * (1 - 1e-12)) return c; }
    return v;
  }
  function Zoomable(svg, redraw) {
    const z = { svg: svg, base: [0, 0, 1, 1], k: 1, cx: 0.5, cy: 0.5, redraw: redraw };
    z.view = function () {
      const [x0, y0, x1, y1] = z.base, w = (x1 - x0) / z.k, h = (y1 - y0) / z.k;
      const cx = x0 + z.cx * (x1 - x0), cy = y0 + z.cy * (y1 - y0);
      return [cx - w / 2, cy - h / 2, w, h];
    };
    z.px = function () {                     // drawing units per screen pixel
      const v = z.view(), cw = svg.clientWidth || 400, ch = svg.clientHeight || 300;
      return Math.max(v[2] / cw, v[3] / ch);
    };
    z.apply = function () {
      const v = z.view();
      svg.setAttribute("viewBox", [r3(v[0]), r3(-v[1] - v[3]), r3(v[2]), r3(v[3])].join(" "));
      svg.setAttribute("font-size", r3(LETTER * z.px()));
    };
    z.fit = function (box, marginPx) {       // the base view: box plus a margin of marginPx screen pixels
      const cw = svg.clientWidth || 400, ch = svg.clientHeight || 300;
      const w = Math.max(box[2] - box[0], 1e-6), h = Math.max(box[3] - box[1], 1e-6);
      const s = Math.max(w / Math.max(cw - 2 * marginPx, 40), h / Math.max(ch - 2 * marginPx, 40));
      const mx = (cw * s - w) / 2, my = (ch * s - h) / 2;
      z.base = [box[0] - mx, box[1] - my, box[2] + mx, box[3] + my];
      z.apply();
    };
    const toDrawing = (ev) => {
      const r = svg.getBoundingClientRect(), v = z.view(), s = z.px();
      const fx0 = (r.width - v[2] / s) / 2, fy0 = (r.height - v[3] / s) / 2;
      return [(ev.clientX - r.left - fx0) * s + v[0], v[1] + v[3] - (ev.clientY - r.top - fy0) * s];
    };
    const setCentre = (p, q) => {              // drawing point p to stay under the screen point q
      const [x0, y0, x1, y1] = z.base;
      z.cx = z.cx + (p[0] - q[0]) / (x1 - x0);
      z.cy = z.cy + (p[1] - q[1]) / (y1 - y0);
    };
    svg.addEventListener("wheel", (ev) => {
      ev.preventDefault();
      const before = toDrawing(ev);
      z.k = Math.min(40, Math.max(0.5, z.k * Math.exp(-ev.deltaY * 0.0015)));
      z.apply();
      setCentre(before, toDrawing(ev));
      z.apply();
      z.redraw();
    }, { passive: false });
    let drag = null;
    svg.addEventListener("pointerdown", (ev) => { drag = { at: toDrawing(ev), id: ev.pointerId }; svg.setPointerCapture(ev.pointerId); });
    svg.addEventListener("pointermove", (ev) => {
      if (!drag || drag.id !== ev.pointerId) return;
      setCentre(drag.at, toDrawing(ev));
      z.apply();
    });
    const end = () => { if (drag) { drag = null; z.redraw(); } };
    svg.addEventListener("pointerup", end);
    svg.addEventListener("pointercancel", end);
    svg.addEventListener("dblclick", () => { z.k = 1; z.cx = 0.5; z.cy = 0.5; z.apply(); z.redraw(); });
    z.place = function (centre, s) {          // the base view: centre at s drawing units per screen pixel
      const cw = svg.clientWidth || 400, ch = svg.clientHeight || 300;
      z.base = [centre[0] - cw * s / 2, centre[1] - ch * s / 2, centre[0] + cw * s / 2, centre[1] + ch * s / 2];
      z.apply();
    };
    svg.setAttribute("tabindex", "0");       // the keys: + − zoom, arrows pan, 0 (or Home) the whole drawing
    svg.addEventListener("keydown", (ev) => {
      if (ev.altKey || ev.ctrlKey || ev.metaKey) return;
      const pan = { ArrowLeft: [-1, 0], ArrowRight: [1, 0], ArrowUp: [0, 1], ArrowDown: [0, -1] }[ev.key];
      if (ev.key === "+" || ev.key === "=") z.k = Math.min(40, z.k * 1.25);
      else if (ev.key === "-" || ev.key === "_") z.k = Math.max(0.5, z.k / 1.25);
      else if (ev.key === "0" || ev.key === "Home") { z.k = 1; z.cx = 0.5; z.cy = 0.5; }
      else if (pan) { z.cx += pan[0] * 0.1 / z.k; z.cy += pan[1] * 0.1 / z.k; }
      else return;
      ev.preventDefault();
      ev.stopPropagation();
      z.apply();
      z.redraw();
    });
    return z;
  }

  // -- labels placed off the lines and off each other ----------------------------------------------------
  function clipHits(a, b, box) {             // does the segment ab meet the box? (Liang–Barsky)
    let t0 = 0, t1 = 1;
    const dx = b[0] - a[0], dy = b[1] - a[1];
    const p = [-dx, dx, -dy, dy], q = [a[0] - box[0], box[2] - a[0], a[1] - box[1], box[3] - a[1]];
    for (let i = 0; i < 4; i++) {
      if (p[i] === 0) { if (q[i] < 0) return false; continue; }
      const t = q[i] / p[i];
      if (p[i] < 0) { if (t > t1) return false; if (t > t0) t0 = t; } else { if (t < t0) return false; if (t < t1) t1 = t; }
    }
    return true;
  }
  const OFFSETS = [[1, 1], [1, -1], [-1, 1], [-1, -1], [1, 0], [-1, 0], [0, 1], [0, -1],
    [1, 0.5], [-1, 0.5], [1, -0.5], [-1, -0.5], [0.5, 1], [-0.5, 1], [0.5, -1], [-0.5, -1]];
  function placeLabels(g, labels, segs, px, boxes) {
    // labels: {at:[x,y], text, cls, prefer:[dx,dy]}; segs: [[a,b]] in drawing units; boxes: taken boxes
    const size = LETTER * px, taken = boxes || [];
    const vb = g.ownerSVGElement && g.ownerSVGElement.viewBox.baseVal;       // the view: a letter kept inside it
    const view = vb && vb.width ? [vb.x, -(vb.y + vb.height), vb.x + vb.width, -vb.y] : null;
    // a letter nearer another point than its own reads as that point's: each box is kept nearer its own
    const boxDist = (b, p) => Math.hypot(Math.max(b[0] - p[0], 0, p[0] - b[2]), Math.max(b[1] - p[1], 0, p[1] - b[3]));
    const anchors = labels.map((lb) => lb.at);
    labels.forEach((lb) => {
      const t = el("text", { x: 0, y: 0, class: "lbl " + (lb.cls || "") }, g);
      svgMarkup(t, lb.text, size);
      let bb;
      try { bb = t.getBBox(); } catch (e) { bb = { x: 0, y: -size, width: size * 0.65 * lb.text.length, height: size * 1.3 }; }
      const w = bb.width + 2 * px, h = bb.height + 2 * px, asc = -bb.y;
      const gap = 4.5 * px;                    // clear of the point's own circle (3.5 px)
      const order = lb.prefer ? OFFSETS.slice().sort((u, v) => (v[0] * lb.prefer[0] + v[1] * lb.prefer[1]) - (u[0] * lb.prefer[0] + u[1] * lb.prefer[1])) : OFFSETS;
      let best = null;
      order.forEach((o, rank) => {
        for (const far of [1, 1.6, 2.2, 3]) {
          const cx = lb.at[0] + o[0] * (w / 2 + gap) * far, cy = lb.at[1] + o[1] * (h / 2 + gap) * far;
          const box = [cx - w / 2, cy - h / 2, cx + w / 2, cy + h / 2];
          let cost = rank + (far > 2.5 ? 24 : far > 2 ? 12 : far > 1 ? 6 : 0);
          const own = boxDist(box, lb.at);
          anchors.forEach((p) => {
            if (Math.abs(p[0] - lb.at[0]) + Math.abs(p[1] - lb.at[1]) > 1e-6 && boxDist(box, p) < own) cost += 60;     // below a line crossed (100): never overprint
          });
          taken.forEach((b) => { if (b[0] < box[2] && box[0] < b[2] && b[1] < box[3] && box[1] < b[3]) cost += 1000; });
          segs.forEach((s) => { if (clipHits(s[0], s[1], box)) cost += 100; });
          if (view && (box[0] < view[0] || box[1] < view[1] || box[2] > view[2] || box[3] > view[3])) cost += 500;
          if (!best || cost < best.cost) best = { cost: cost, box: box };
        }
      });
      const b = best.box;
      t.setAttribute("x", r3(b[0] + px - bb.x));
      t.setAttribute("y", r3(-(b[3] - px) + asc));
      taken.push(b);
    });
    return taken;
  }

  // -- the grid, in the turn from position 0 -----------------------------------------------------------------
  const G = D.grid, S = D.scheme, N = G.phi.length;
  const muL = D.scales.mu_l, muV = D.scales.mu_v, muA = D.scales.mu_a;
  const turnOf = (phi) => { const t = ((((phi - D.phi0) * (D.omega1 >= 0 ? 1 : -1)) % 360) + 360) % 360; return t > 360 - 1e-7 ? 0 : t; };
  const order = G.phi.map((_, i) => i).sort((a, b) => turnOf(G.phi[a]) - turnOf(G.phi[b]));
  const rank = new Array(N);
  order.forEach((i, k) => { rank[i] = k; });
  function at(name, i) {
    if (S.frame[name]) return S.frame[name];
    const p = G.points[name];
    return [p.x[i] / muL, p.y[i] / muL];
  }
  const labKey = {};
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
  function nearestTurn(turn) {
    let best = 0, gap = 1e9;
    for (let i = 0; i < N; i++) {
      const d = Math.abs(((turnOf(G.phi[i]) - turn + 540) % 360) - 180);
      if (d < gap - 1e-12) { gap = d; best = i; }
    }
    return best;
  }
  const label = (name) => (S.labels && S.labels[name]) || name;
  const lower = (name) => { const m = label(name); return m.charAt(0).toLowerCase() + m.slice(1); };

  // -- the mechanism ---------------------------------------------------------------------------------------
  const mechSvg = $("mech");
  let index = nearest(D.open ? D.open.phi : D.phi0);     // where the plans read (explorer.py opening)
  const mechZ = Zoomable(mechSvg, () => drawMechanism(index));
  const mechBox = [1e9, 1e9, -1e9, -1e9];
  Object.values(S.frame).forEach((p) => grow(mechBox, p));
  Object.keys(G.points).forEach((n) => { for (let i = 0; i < N; i += 1) grow(mechBox, at(n, i)); });
  mechSvg.style.aspectRatio = String(r3(Math.min(2.2, Math.max(0.75, (mechBox[2] - mechBox[0] + 30) / (mechBox[3] - mechBox[1] + 30)))));
  function drawMechanism(i) { drawMechanismIn(mechSvg, mechZ, i, null); }
  function drawMechanismIn(svgEl, zoom, i, mark) {
    // mark (the replay's step): the link of the step highlighted, its direction line through the point,
    // the plan's segment carried to the point and the sense it turns the link
    clear(svgEl);
    const px = zoom.px(), segs = [], boxes = [];     // boxes: the joints and the ground hatches, kept clear of letters
    const g = el("g", {}, svgEl);
    const seg = (a, b, cls) => { line(g, a, b, cls); segs.push([a, b]); };
    S.guides.forEach((gd) => {
      const u = [Math.cos(gd.angle * Math.PI / 180), Math.sin(gd.angle * Math.PI / 180)];
      let lo = 1e9, hi = -1e9;
      for (let k = 0; k < N; k++) {
        const p = at(gd.point, k), t = (p[0] - gd.through[0]) * u[0] + (p[1] - gd.through[1]) * u[1];
        lo = Math.min(lo, t); hi = Math.max(hi, t);
      }
      seg([gd.through[0] + (lo - 12) * u[0], gd.through[1] + (lo - 12) * u[1]],
        [gd.through[0] + (hi + 12) * u[0], gd.through[1] + (hi + 12) * u[1]], "guide");
    });
    S.trajectories.forEach((n) => poly(g, order.map((k) => at(n, k)), "traj", true));
    const labels = [];
    const O = S.frame[S.crank.pivot];
    D.positions.forEach((p) => {
      const A = at(S.crank.pin, nearest(p.phi));
      el("circle", { cx: r3(A[0]), cy: r3(-A[1]), r: r3(3 * px), class: "labpos" }, g);
      if (p.index !== null) labels.push({ at: A, text: String(p.index), cls: "exact", prefer: [A[0] - O[0], A[1] - O[1]] });
    });
    S.pivots.forEach((n) => {
      const p = S.frame[n];
      poly(g, [p, [p[0] - 3, p[1] - 5], [p[0] + 3, p[1] - 5]], "ground", true);
      line(g, [p[0] - 5, p[1] - 5], [p[0] + 5, p[1] - 5], "ground");
      for (let k = -4; k <= 4; k += 2) line(g, [p[0] + k, p[1] - 5], [p[0] + k - 1.5, p[1] - 6.5], "ground");
      boxes.push([p[0] - 6.5, p[1] - 6.5, p[0] + 5, p[1]]);
    });
    S.links.forEach((L) => {
      const pts = L.joints.map((j) => at(j, i));
      // a coulisse along its guide, as the sheets draw it (Python's slot_line at every angle): to its end B
      ((G.slots || {})[L.name] || []).forEach((per) => { const e = per[i]; seg([e[0], e[1]], [e[2], e[3]], "link"); });
      if (pts.length >= 2) {           // the sheets' outline (model.linkshape): the bar to D, the plate round E
        const shape = (L.outline && L.outline.length >= 2 ? L.outline : L.joints).map((j) => at(j, i));
        poly(g, shape, "link", false);
        for (let k = 0; k + 1 < shape.length; k++) segs.push([shape[k], shape[k + 1]]);
      }
      if (L.block) {
        const c = at(L.block, i), th = G.links[L.name].theta[i] * Math.PI / 180;
        const u = [Math.cos(th), Math.sin(th)], v = [-u[1], u[0]];
        const corner = (sx, sy) => [c[0] + u[0] * sx * 4.5 + v[0] * sy * 2.5, c[1] + u[1] * sx * 4.5 + v[1] * sy * 2.5];
        const cs = [corner(-1, -1), corner(1, -1), corner(1, 1), corner(-1, 1)];
        poly(g, cs, "block", true);
        for (let k = 0; k < 4; k++) segs.push([cs[k], cs[(k + 1) % 4]]);
      }
    });
    const seen = {};
    S.links.forEach((L) => L.joints.forEach((j) => {
      if (seen[j]) return;
      seen[j] = 1;
      const p = at(j, i);
      const r = Math.max(0.9, 3.5 * px);
      el("circle", { cx: r3(p[0]), cy: r3(-p[1]), r: r3(r), class: "joint" }, g);
      boxes.push([p[0] - r, p[1] - r, p[0] + r, p[1] + r]);
      labels.unshift({ at: p, text: label(j) });
    }));
    S.links.forEach((L) => (L.points || []).forEach((n) => {      // a link's own points beyond its joints: D, E
      if (seen[n]) return;
      seen[n] = 1;
      const p = at(n, i), r = Math.max(0.7, 2.5 * px);
      el("circle", { cx: r3(p[0]), cy: r3(-p[1]), r: r3(r), class: "point", "data-point": n }, g);
      boxes.push([p[0] - r, p[1] - r, p[0] + r, p[1] + r]);
      labels.push({ at: p, text: label(n) });
    }));
    Object.keys(G.points).forEach((n) => {
      if (seen[n] || !/^S/.test(n)) return;
      const p = at(n, i);
      el("circle", { cx: r3(p[0]), cy: r3(-p[1]), r: r3(2.5 * px), class: "labpos" }, g);
      labels.push({ at: p, text: label(n) });
    });
    if (mark) markMechanism(svgEl, g, i, mark, px, segs);
    const lg = el("g", svgEl === mechSvg ? { id: "mech-labels" } : { class: "rmech-labels" }, svgEl);
    omega1(svgEl, g, lg, i, px, segs, placeLabels(lg, labels, segs, px, boxes.slice()));
    svgEl.setAttribute("data-kept", JSON.stringify(boxes.map((b) => b.map(r3))));
  }
  function omega1(svgEl, g, lg, i, px, segs, taken) {
    // ω1: an arc about the crank's pivot in its sense (as the sheets draw it), crossing no link and no
    // letter, off the support below, nearest opposite the crank; then its letter
    const O = S.frame[S.crank.pivot], A = at(S.crank.pin, i), up = Math.atan2(A[1] - O[1], A[0] - O[0]), R = 20 * px;
    const gap = (a, b) => Math.abs(((a - b + 3 * Math.PI) % (2 * Math.PI)) - Math.PI);
    const sense = D.omega1 >= 0 ? 1 : -1;
    const arc = (m) => { const out = []; for (let k = 0; k <= 12; k++) { const t = m - sense * 0.75 + sense * 1.5 * k / 12; out.push([O[0] + R * Math.cos(t), O[1] + R * Math.sin(t)]); } return out; };
    const side = (a, b, c) => Math.sign((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]));
    const meets = (p, q, a, b) => side(p, q, a) * side(p, q, b) < 0 && side(a, b, p) * side(a, b, q) < 0;
    let mid = up + Math.PI, best = 1e9;
    for (let k = 0; k < 24; k++) {
      const m = up + Math.PI + (k % 2 ? 1 : -1) * Math.ceil(k / 2) * Math.PI / 12, a = arc(m);
      let cost = Math.ceil(k / 2) + (gap(m, -Math.PI / 2) < 1.2 ? 50 : 0);     // the support: ±45° about down, the arc ±43°
      for (let j = 0; j < 12; j++) segs.forEach((sg) => { if (meets(a[j], a[j + 1], sg[0], sg[1])) cost += 100; });
      a.forEach((p) => taken.forEach((b) => { if (p[0] > b[0] && p[0] < b[2] && p[1] > b[1] && p[1] < b[3]) cost += 100; }));
      const c = [O[0] + (R + 16 * px) * Math.cos(m), O[1] + (R + 16 * px) * Math.sin(m)];      // room for its letter
      const lb = [c[0] - 12 * px, c[1] - 9 * px, c[0] + 12 * px, c[1] + 9 * px];
      segs.forEach((sg) => { if (clipHits(sg[0], sg[1], lb)) cost += 30; });
      taken.forEach((b) => { if (b[0] < lb[2] && lb[0] < b[2] && b[1] < lb[3] && lb[1] < b[3]) cost += 30; });
      if (cost < best) { best = cost; mid = m; }
    }
    const pts = arc(mid);
    poly(g, pts, "omega1", false);
    arrow(g, pts[10], pts[12], "omega1", px * 0.8);
    for (let k = 0; k < 12; k++) segs.push([pts[k], pts[k + 1]]);
    placeLabels(lg, [{ at: [O[0] + 1.15 * R * Math.cos(mid), O[1] + 1.15 * R * Math.sin(mid)], text: "ω_1",
      prefer: [Math.cos(mid), Math.sin(mid)] }], segs, px, taken);
    svgEl.setAttribute("data-omega1", JSON.stringify({ sense: sense, from: pts[0].map(r3), to: pts[12].map(r3), centre: O }));
  }
  function guideAngle(point) {
    const gd = S.guides.find((x) => x.point === point);
    return gd ? gd.angle * Math.PI / 180 : null;
  }
  function markMechanism(svgEl, g, i, mark, px, segs) {
    svgEl.removeAttribute("data-link");
    svgEl.removeAttribute("data-line");
    if (mark.link && mark.link.length === 2 && mark.link[0] !== mark.link[1]) {
      const a = at(mark.link[0], i), b = at(mark.link[1], i);
      line(g, a, b, "mark-link");
      svgEl.setAttribute("data-link", mark.link.join(" "));
      svgEl.setAttribute("data-link-xy", JSON.stringify([a, b].map((p) => p.map(r3))));
    }
    const P = mark.point && (S.frame[mark.point] || G.points[mark.point]) ? at(mark.point, i) : null;
    if (P) el("circle", { cx: r3(P[0]), cy: r3(-P[1]), r: r3(7 * px), class: "meet" }, g);
    let u = null;
    if (P && mark.dir) u = mark.dir;
    else if (P && mark.line && mark.link) {
      const a = at(mark.link[0], i), b = at(mark.link[1], i), d = [b[0] - a[0], b[1] - a[1]];
      u = mark.line === "perp" ? [-d[1], d[0]] : d;
    } else if (P && mark.line === "guide") {
      const th = guideAngle(mark.guide);
      if (th !== null) u = [Math.cos(th), Math.sin(th)];
    }
    if (u) {                                // the direction line, through the point, as it is named
      const n = Math.hypot(u[0], u[1]) || 1, L = 160 * px;
      const e = [u[0] / n * L, u[1] / n * L];
      line(g, [P[0] - e[0], P[1] - e[1]], [P[0] + e[0], P[1] + e[1]], "mark-line");
      svgEl.setAttribute("data-line", JSON.stringify([u[0] / n, u[1] / n].map((v) => Math.round(v * 1e6) / 1e6)));
    }
    if (P && mark.carry) {                  // the plan's segment carried to the point: the sense of ω or ε
      const n = Math.hypot(mark.carry[0], mark.carry[1]) || 1, L = 55 * px;
      const tip = [P[0] + mark.carry[0] / n * L, P[1] + mark.carry[1] / n * L];
      arrow(g, P, tip, "carry", px);
      svgEl.setAttribute("data-carry", JSON.stringify([mark.carry[0] / n, mark.carry[1] / n].map((v) => Math.round(v * 1e6) / 1e6)));
      const O = at(mark.link[0], i), R = 22 * px, a0 = Math.atan2(P[1] - O[1], P[0] - O[0]), sense = mark.sense || 0;
      if (sense) {                           // an arc about the link's other end in that sense, with its head
        const pts = [];
        for (let k = 0; k <= 12; k++) { const t = a0 - sense * 0.9 + sense * 1.8 * k / 12; pts.push([O[0] + R * Math.cos(t), O[1] + R * Math.sin(t)]); }
        poly(g, pts, "carry", false);
        arrow(g, pts[10], pts[12], "carry", px * 0.8);
        svgEl.setAttribute("data-sense", String(sense));
      }
    } else svgEl.removeAttribute("data-carry");
  }

  // -- the plans of the current angle -----------------------------------------------------------------------
  const recByKey = { velocity: {}, acceleration: {} };
  D.records.forEach((r) => { recByKey[r.kind][r.key] = r; });
  function planVector(kind, name, i) {
    const p = G.points[name], mu = kind === "velocity" ? muV : muA;
    return kind === "velocity" ? [p.vx[i] / mu, p.vy[i] / mu] : [p.ax[i] / mu, p.ay[i] / mu];
  }
  const imageOf = (kind, name, i) => (S.frame[name] ? [0, 0] : planVector(kind, name, i));
  const pts = (f) => { const out = []; for (let k = 0; k < f.length; k += 2) out.push([f[k], f[k + 1]]); return out; };
  function recordBox(r, box) { r.items.forEach((it) => pts(it[1]).forEach((p) => grow(box, p))); }
  const planSvg = { velocity: $("vplan"), acceleration: $("aplan") };
  const planZ = {};
  const turnBox = {};
  ["velocity", "acceleration"].forEach((kind) => {
    planZ[kind] = Zoomable(planSvg[kind], () => drawPlan(kind, index));
    const box = [0, 0, 0, 0];
    Object.keys(G.points).forEach((n) => { for (let i = 0; i < N; i++) grow(box, planVector(kind, n, i)); });
    Object.values(recByKey[kind]).forEach((r) => recordBox(r, box));
    turnBox[kind] = box;
  });
  function angleBox(kind, i) {
    const box = [0, 0, 0, 0];
    Object.keys(G.points).forEach((n) => grow(box, planVector(kind, n, i)));
    const lab = labKey[i];
    if (lab && recByKey[kind][lab.key]) recordBox(recByKey[kind][lab.key], box);
    return box;
  }
  function drawItems(g, r, upto, current, px, segs) {     // a record's primitives up to a step
    const stepOf = {};
    r.steps.forEach((s, k) => s.items.forEach((j) => { stepOf[j] = k; }));
    r.items.forEach((it, j) => {
      const [kind, f, role, radius] = it;
      const s = stepOf[j];
      if (upto !== undefined && role !== "pole" && (s === undefined || s > upto)) return;
      const hl = upto !== undefined && s === current ? " hl" : "";
      const p = pts(f);
      if (kind === "vector") { arrow(g, p[0], p[1], "g-vec" + hl, px); segs.push([p[0], p[1]]); }
      else if (kind === "segment") { line(g, p[0], p[1], (role === "direction" || role === "construction" ? "g-line" : "g-vec") + hl); segs.push([p[0], p[1]]); }
      else if (kind === "point") el("circle", { cx: r3(p[0][0]), cy: r3(-p[0][1]), r: r3(2.5 * px), class: "g-vec" }, g);
      else if (kind === "circle") el("circle", { cx: r3(p[0][0]), cy: r3(-p[0][1]), r: radius, class: "g-line" + hl }, g);
      else if (kind === "polyline" || kind === "polygon") {
        poly(g, p, "g-line" + hl, kind === "polygon");
        for (let k = 0; k + 1 < p.length; k++) segs.push([p[k], p[k + 1]]);
      }
    });
  }
  const fitScale = (svg, box, margin) => {   // drawing units per screen pixel that fit box in the panel (Zoomable.fit)
    const cw = svg.clientWidth || 400, ch = svg.clientHeight || 300;
    return Math.max(Math.max(box[2] - box[0], 1e-6) / Math.max(cw - 2 * margin, 40), Math.max(box[3] - box[1], 1e-6) / Math.max(ch - 2 * margin, 40));
  };
  const planMu = { velocity: muV, acceleration: muA };
  function planCaption(kind, mu) {           // the caption says the scale the plan is drawn at now
    const cap = $(kind === "velocity" ? "cap-vplan" : "cap-aplan");
    setMarkup(cap, (kind === "velocity" ? W().vplan : W().aplan) + fmtG(mu, 4) + " " + unit(kind === "velocity" ? "(m/s)/mm" : "(m/s²)/mm")
      + (mu !== (kind === "velocity" ? muV : muA) ? W().ofAngle : ""));
    cap.setAttribute("data-mu", String(mu));
    $(kind === "velocity" ? "vplan" : "aplan").setAttribute("aria-label", cap.textContent + "; " + W().zoomKeys);
  }
  function drawPlan(kind, i) {
    const svg = planSvg[kind], z = planZ[kind];
    if ($("per-angle").checked) {
      // the plan of this angle at the standard scale that fills the panel the fixed-scale plan fills (as
      // a draftsman would choose it for this angle alone): μ' ≥ μ·(its extent)/(the turn's extent)
      const box = angleBox(kind, i), s0 = fitScale(svg, turnBox[kind], 28), s1 = fitScale(svg, box, 28);
      const mu = Math.min(kind === "velocity" ? muV : muA, standardAtLeast((kind === "velocity" ? muV : muA) * s1 / s0));
      z.k = 1; z.cx = 0.5; z.cy = 0.5;
      z.place([(box[0] + box[2]) / 2, (box[1] + box[3]) / 2], s0 * mu / (kind === "velocity" ? muV : muA));
      planMu[kind] = mu;
    } else planMu[kind] = kind === "velocity" ? muV : muA;
    planCaption(kind, planMu[kind]);
    clear(svg);
    const px = z.px(), g = el("g", {}, svg), segs = [];
    S.links.forEach((L) => {
      // the link's image, similar to it: the same outline through the images of its points (a coulisse's too)
      const names = L.outline && L.outline.length >= 2 ? L.outline : L.joints;
      if (L.name === S.crank.link || names.length < 2) return;
      const fig = names.map((j) => imageOf(kind, j, i));
      poly(g, fig, "figure", false);
    });
    Object.keys(G.points).forEach((n) => { const p = planVector(kind, n, i); arrow(g, [0, 0], p, "exact", px); segs.push([[0, 0], p]); });
    const lab = labKey[i], rec = lab && recByKey[kind][lab.key];
    const labels = [];
    if (rec) {
      drawItems(el("g", {}, svg), rec, undefined, undefined, px, segs);
      rec.points.forEach((q) => labels.push({ at: [q[1], q[2]], text: q[0] }));
    } else {
      labels.push({ at: [0, 0], text: kind === "velocity" ? "p_v" : "π" });
      Object.keys(G.points).forEach((n) => labels.push({ at: planVector(kind, n, i), text: lower(n), cls: "exact" }));
    }
    placeLabels(el("g", {}, svg), labels, segs, px);
  }

  // -- the values' table --------------------------------------------------------------------------------------
  function rowSymbol(row) {
    if (row.symbol) return row.symbol;          // the sheets' own (report.plans.symbol): ω_3, v_A3A2
    if (row.source === "point") return (row.plan === "velocity" ? "v_{" : "a_{") + row.name + "}";
    if (row.source === "omega") return "ω_{" + row.name + "}";
    if (row.source === "epsilon") return "ε_{" + row.name + "}";
    if (row.source === "slide_v") return "v^r_{" + row.name + "}";
    return "a^k_{" + row.name + "}";
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
  const cells = D.rows.map((row) => {
    const trow = document.createElement("tr");
    trow.setAttribute("data-q", row.q);
    trow.setAttribute("data-plan", row.plan);
    const th = document.createElement("th");
    trow.appendChild(th);
    const td = ["graphical", "exact", "error"].map((c) => { const t = document.createElement("td"); t.className = c; trow.appendChild(t); return t; });
    tbody.appendChild(trow);
    return [row, th, td];
  });
  function updateTable(i) {
    const lab = labKey[i], got = lab ? D.readings[String(lab.key)] || {} : {};
    cells.forEach(([row, th, td]) => {
      setMarkup(th, rowSymbol(row) + ", " + unit(row.unit));
      const x = exactValue(row, i), r = got[row.q];
      td[1].textContent = fmtG(x, 4);
      td[1].setAttribute("data-value", String(x));
      if (r) {
        const gv = row.source === "slide_v" && x < 0 ? -r[1] : r[1];
        td[0].textContent = fmtG(gv, 4) + (r[0] !== null ? " (" + fx(r[0], 1) + " " + unit("mm") + ")" : "");
        td[0].setAttribute("data-value", String(gv));
        td[2].textContent = r[2] === null ? "—" : fx(r[2], 2);
        td[2].className = "error" + (r[2] !== null && Math.abs(r[2]) > 5 ? " bad" : "");
      } else {
        td[0].textContent = "";
        td[0].removeAttribute("data-value");
        td[2].textContent = "";
        td[2].className = "error";
      }
    });
  }

  // -- warnings -------------------------------------------------------------------------------------------------
  function updateWarnings(i) {
    const ul = $("warnings");
    ul.textContent = "";
    const add = (kind, s) => { const li = document.createElement("li"); li.setAttribute("data-kind", kind); setMarkup(li, s); ul.appendChild(li); };
    const half = D.step / 2 + 1e-6;
    D.warnings.extremes.forEach((e) => { if (Math.abs(((G.phi[i] - e + 540) % 360) - 180) <= half) add("extreme", fill(W().extreme, { a: fx(e, 2) })); });
    Object.keys(G.crossing).forEach((g) => { const a = G.crossing[g][i]; if (a < D.warnings.small) add("crossing", fill(W().crossing, { g: g, a: fx(a, 1) })); });
    const lab = labKey[i];
    if (lab && D.warnings.plans[String(lab.key)]) tr(D.warnings.plans[String(lab.key)]).forEach((s) => add("plan", s));
    if (!ul.firstChild) add("none", W().none);
  }
  function allWarnings() {
    const ul = $("warnings-all");
    ul.textContent = "";
    const add = (s) => { const li = document.createElement("li"); setMarkup(li, s); ul.appendChild(li); };
    D.warnings.extremes.forEach((e) => add(fill(W().extreme, { a: fx(e, 2) })));
    Object.keys(G.crossing).forEach((g) => {
      let lo = 90, where = 0;
      G.crossing[g].forEach((a, i) => { if (a < lo) { lo = a; where = G.phi[i]; } });
      if (lo < D.warnings.small) add(fill(W().crossing, { g: g, a: fx(lo, 1) }) + ", φ = " + fx(where, 1) + "°");
    });
    Object.keys(D.warnings.plans).forEach((k) => tr(D.warnings.plans[k]).forEach((s) => add(W().lab + " " + k + ": " + s)));
    tr(D.warnings.study).forEach(add);
  }

  // -- the s–v–a diagrams: click or drag to seek; ← → on the focused diagrams --------------------------------
  // laid out in screen pixels (the lettering 13 px at any width), redrawn when the window changes
  const dg = D.diagrams, dsvg = $("diagrams");
  let cursor = null, DX = { x0: 0, w: 1 };
  function drawDiagrams() {
    clear(dsvg);
    cursor = null;
    if (!dg) { $("diagrams-section").hidden = true; return; }
    const width = Math.max(280, dsvg.clientWidth || 600), size = LETTER;
    const left = 78, right = 18, CH = Math.round(Math.min(170, Math.max(90, width * 0.16))), GAP = 34;
    const WIDTH = width - left - right;
    DX = { x0: left, w: WIDTH };
    const height = 3 * (CH + GAP) + 30;
    dsvg.setAttribute("viewBox", [0, 0, width, height].join(" "));
    dsvg.style.height = height + "px";
    dsvg.setAttribute("font-size", String(size));
    dsvg.setAttribute("data-x0", String(left));
    dsvg.setAttribute("data-width", String(WIDTH));
    ["s", "v", "a"].forEach((key, row) => {
      const y0 = 8 + row * (CH + GAP);
      const ex = dg.exact[key], ch = dg.chords[key];
      let lo = Math.min(0, ...ex, ...ch.map((c) => c[1])), hi = Math.max(0, ...ex, ...ch.map((c) => c[1]));
      if (hi - lo < 1e-12) hi = lo + 1;
      const X = (turn) => left + (turn / 360) * WIDTH, Y = (v) => y0 + CH - ((v - lo) / (hi - lo)) * CH;
      const g = el("g", {}, dsvg);
      const ln = (x1, y1, x2, y2, cls) => el("line", { x1: r3(x1), y1: r3(y1), x2: r3(x2), y2: r3(y2), class: cls }, g);
      ln(left, y0, left, y0 + CH, "axis");
      ln(left, Y(0), left + WIDTH, Y(0), "axis");
      for (let t = 30; t <= 360; t += 30) ln(X(t), y0, X(t), y0 + CH, "grid");
      el("polyline", { points: order.map((i) => r3(X(turnOf(G.phi[i]))) + "," + r3(Y(ex[i]))).join(" "), class: "curve" }, g);
      ch.forEach((c) => el("circle", { cx: r3(X(turnOf(c[0]))), cy: r3(Y(c[1])), r: 2.5, class: "chord" }, g));
      const u = { s: dg.unit, v: dg.unit + "/s", a: dg.unit + "/s²" }[key];
      const t1 = el("text", { x: left + 6, y: y0 + size, class: "dtext" }, g);
      svgMarkup(t1, dg.symbols[row] + "_{" + dg.sub + "}, " + unit(u), size);
      const t2 = el("text", { x: left - 4, y: y0 + size * 0.8, class: "dtext", "text-anchor": "end" }, g); t2.textContent = fmtG(hi, 3);
      const t3 = el("text", { x: left - 4, y: y0 + CH, class: "dtext", "text-anchor": "end" }, g); t3.textContent = fmtG(lo, 3);
    });
    const base = 8 + 3 * (CH + GAP) - GAP;
    for (let t = 0; t <= 360; t += 60) {
      const tx = el("text", { x: r3(left + (t / 360) * WIDTH), y: base + size + 2, class: "dtext", "text-anchor": "middle" }, dsvg);
      tx.textContent = String(t);
    }
    const t = el("text", { x: left + WIDTH / 2, y: base + 2 * size + 6, class: "dtext", "text-anchor": "middle" }, dsvg);
    t.textContent = W().turnAxis;
    cursor = el("line", { x1: 0, y1: 4, x2: 0, y2: base + 2, class: "cursor", id: "diagram-cursor" }, dsvg);
    setMarkup($("diagrams-note"), fill(W().diagnote, { n: dg.divisions, d: fmtG(360 / dg.divisions, 4), L: fmtG(dg.L, 4), H1: fmtG(dg.H1, 4),
      H2: fmtG(dg.H2, 4), ms: fmtG(dg.mu.s, 4), mt: fmtG(dg.mu.t, 4), mv: fmtG(dg.mu.v, 4), ma: fmtG(dg.mu.a, 4) }));
    moveCursor();
  }
  function moveCursor() {
    if (!cursor) return;
    const x = r3(DX.x0 + (turnOf(G.phi[index]) / 360) * DX.w);
    cursor.setAttribute("x1", x);
    cursor.setAttribute("x2", x);
  }
  let seeking = false;
  function seek(ev) {
    const p = dsvg.createSVGPoint();
    p.x = ev.clientX; p.y = ev.clientY;
    const q = p.matrixTransform(dsvg.getScreenCTM().inverse());
    show(nearestTurn(Math.min(359.999, Math.max(0, ((q.x - DX.x0) / DX.w) * 360))));
  }
  dsvg.addEventListener("pointerdown", (ev) => { seeking = true; dsvg.setPointerCapture(ev.pointerId); seek(ev); });
  dsvg.addEventListener("pointermove", (ev) => { if (seeking) seek(ev); });
  dsvg.addEventListener("pointerup", () => { seeking = false; });
  dsvg.setAttribute("tabindex", "0");
  dsvg.addEventListener("keydown", (ev) => {       // the diagrams seek by keyboard: a grid step, 10°, the ends
    if (ev.altKey || ev.ctrlKey || ev.metaKey) return;
    const by = { ArrowRight: 1, ArrowUp: 1, ArrowLeft: -1, ArrowDown: -1, PageUp: Math.max(1, Math.round(10 / D.step)),
      PageDown: -Math.max(1, Math.round(10 / D.step)) }[ev.key];
    if (by) stepAngle(by);
    else if (ev.key === "Home") show(order[0]);
    else if (ev.key === "End") show(order[N - 1]);
    else return;
    ev.preventDefault();
    ev.stopPropagation();
  });

  // -- the replay --------------------------------------------------------------------------------------------------
  const sel = $("replay-plan"), rsvg = $("replay");
  let current = null, stepNo = 0, returnTo = null;
  const replayZ = Zoomable(rsvg, () => showStep());
  const rmechSvg = $("rmech"), rmechZ = Zoomable(rmechSvg, () => showStep());
  rmechSvg.style.aspectRatio = mechSvg.style.aspectRatio;     // the mechanism's own shape: a tall one is not shrunk to a 4:3 strip
  function planName(r) {
    return W()[r.kind] + ", " + (r.index !== null ? fill(W().at, { k: r.index }) : "φ = " + fx(r.phi, 1) + "°");
  }
  function choose(k, moveMechanism) {
    current = D.records[k];
    sel.value = String(k);
    stepNo = 0;
    const box = [0, 0, 0, 0];
    recordBox(current, box);
    replayZ.k = 1; replayZ.cx = 0.5; replayZ.cy = 0.5;
    replayZ.fit(box, 30);
    rmechZ.k = 1; rmechZ.cx = 0.5; rmechZ.cy = 0.5;
    rmechZ.fit(mechBox, 20);
    setMarkup($("cap-rmech"), fill(W().rmech, { a: fx(current.phi, 2) }));
    rmechSvg.setAttribute("aria-label", $("cap-rmech").textContent + "; " + W().zoomKeys);
    const ol = $("step-list");
    ol.textContent = "";
    current.steps.forEach((s, n) => {
      const li = document.createElement("li");
      li.setAttribute("data-step", String(n));
      const no = document.createElement("span");
      no.className = "no";
      no.textContent = n + ".";                 // step 0: the pole and the scale
      no.setAttribute("aria-hidden", "true");
      li.appendChild(no);
      const b = document.createElement("button");
      b.type = "button";
      setMarkup(b, tr(s.caption));
      b.addEventListener("click", () => { stepNo = n; showStep(); });
      li.appendChild(b);
      ol.appendChild(li);
    });
    if (moveMechanism) {
      const target = nearest(current.phi);
      if (target !== index) { returnTo = index; show(target, true); }
    }
    updateReturn();
    showStep();
  }
  function showEquation(node, eq) {           // the vector equation, each term barred and underlined as known
    node.textContent = "";
    const box = document.createElement("span");
    box.className = "equation";
    eq.tokens.forEach((t) => {
      if (t.op) { const o = document.createElement("span"); o.className = "op"; o.textContent = t.op; box.appendChild(o); return; }
      const term = document.createElement("span");
      term.className = "term m" + t.m;
      term.setAttribute("data-marks", String(t.m));
      const v = document.createElement("span");
      v.className = "vec";
      setMarkup(v, t.t);
      const note = document.createElement("span");
      note.className = "dir";
      setMarkup(note, tr(t.note) || "\u00a0");
      term.appendChild(v);
      term.appendChild(note);
      box.appendChild(term);
    });
    node.appendChild(box);
    const key = document.createElement("span");
    key.className = "eq-key";
    setMarkup(key, W().eqKey);
    node.appendChild(key);
  }
  function updateReturn() {
    const b = $("replay-return");
    b.hidden = returnTo === null;
    if (returnTo !== null) b.textContent = fill(W().returnTo, { a: fx(G.phi[returnTo], 1) });
  }
  function showStep() {
    if (!current) return;
    clear(rsvg);
    const px = replayZ.px(), segs = [];
    drawItems(el("g", {}, rsvg), current, stepNo, stepNo, px, segs);
    const s = current.steps[stepNo];
    if (s.meet) el("circle", { cx: r3(s.meet[1]), cy: r3(-s.meet[2]), r: r3(7 * px), class: "meet" }, rsvg);
    if (s.scale) el("circle", { cx: 0, cy: 0, r: r3(7 * px), class: "meet", id: "replay-pole" }, rsvg);     // step 0: the pole
    if (s.rate) arrow(rsvg, s.rate.from, s.rate.to, "g-vec hl rate", px);           // the segment ω (ε) is read from
    if (s.equation && !s.items.length && !s.meet) {                                  // the equation's known points
      current.points.forEach((q) => { if (q[3] < stepNo) el("circle", { cx: r3(q[1]), cy: r3(-q[2]), r: r3(5 * px), class: "meet known" }, rsvg); });
    }
    drawMechanismIn(rmechSvg, rmechZ, nearest(current.phi), s.mech || null);
    const labels = [];
    current.points.forEach((q) => { if (q[3] <= stepNo) labels.push({ at: [q[1], q[2]], text: q[0], cls: q[3] === stepNo ? "new" : "" }); });
    const lg = el("g", { id: "replay-labels" }, rsvg);
    placeLabels(lg, labels, segs, px);
    setMarkup($("step-caption"), tr(s.caption));
    if (s.equation) showEquation($("step-eq"), s.equation); else setMarkup($("step-eq"), tr(s.eq));
    const c = $("step-count");
    c.textContent = fill(W().step, { k: stepNo, n: current.steps.length - 1 });
    c.setAttribute("data-step", String(stepNo));
    document.querySelectorAll("#step-list li").forEach((li, n) => {
      li.className = n < stepNo ? "done" : n === stepNo ? "current" : "todo";
      const b = li.querySelector("button");
      if (n === stepNo) b.setAttribute("aria-current", "step"); else b.removeAttribute("aria-current");
    });
    const ol = $("step-list"), cur = ol.children[stepNo];    // the list scrolls to the current step (not the page)
    if (cur) {
      if (cur.offsetTop < ol.scrollTop) ol.scrollTop = Math.max(0, cur.offsetTop - 4);
      else if (cur.offsetTop + cur.offsetHeight > ol.scrollTop + ol.clientHeight) ol.scrollTop = cur.offsetTop + cur.offsetHeight - ol.clientHeight + 4;
    }
  }
  function stepBy(d) { if (!current) return; stepNo = Math.max(0, Math.min(current.steps.length - 1, stepNo + d)); showStep(); }
  sel.addEventListener("change", () => choose(parseInt(sel.value, 10), true));
  $("step-next").addEventListener("click", () => stepBy(1));
  $("step-back").addEventListener("click", () => stepBy(-1));
  $("step-first").addEventListener("click", () => { stepNo = 0; showStep(); });
  $("step-last").addEventListener("click", () => { stepNo = current.steps.length - 1; showStep(); });
  $("replay-return").addEventListener("click", () => { if (returnTo !== null) { const k = returnTo; returnTo = null; show(k, true); updateReturn(); } });

  // -- the self-check: the student's own lengths against the exact values ---------------------------------------
  const checkSel = $("check-position");
  const checkKeys = Object.keys(D.check || {}).filter((k) => D.check[k].length);
  function checkRow(row, input, out) {
    const [, , , mu, exact] = row;
    const mm = parseFloat(String(input.value).replace(",", "."));
    if (!isFinite(mm) || input.value === "") { out[0].textContent = ""; out[1].textContent = ""; out[1].removeAttribute("data-value"); return; }
    const v = mm * mu;
    out[0].textContent = fmtG(v, 4);
    if (exact > 0) {
      const e = 100 * (v - exact) / exact;
      out[1].textContent = fx(e, 2);
      out[1].setAttribute("data-value", String(e));
      out[1].className = Math.abs(e) > 5 ? "bad" : "";
    } else { out[1].textContent = "—"; }
  }
  function drawCheck() {
    const key = checkSel.value, rows = D.check[key] || [];
    const head = $("check").querySelector("thead"), body = $("check").querySelector("tbody");
    head.textContent = "";
    body.textContent = "";
    const hr = document.createElement("tr");
    [W().q, W().mu, W().yourMm, W().value, W().exact, W().error, W().theirs].forEach((h, k) => {
      const th = document.createElement("th");
      setMarkup(th, h);
      if (k === 6) th.className = "reveal";
      hr.appendChild(th);
    });
    head.appendChild(hr);
    rows.forEach((row) => {
      const [plan, entry, symbol, mu, exact, mm, err] = row;
      const trow = document.createElement("tr");
      trow.setAttribute("data-entry", plan + ":" + entry);
      const th = document.createElement("th");
      setMarkup(th, symbol + ", " + unit(plan === "velocity" ? "m/s" : "m/s²"));
      trow.appendChild(th);
      const tdMu = document.createElement("td"); tdMu.textContent = fmtG(mu, 4); trow.appendChild(tdMu);
      const tdIn = document.createElement("td");
      const input = document.createElement("input");
      input.type = "text"; input.inputMode = "decimal"; input.setAttribute("aria-label", symbol.replace(/[_^{}]/g, "") + ", " + unit("mm"));
      tdIn.appendChild(input); trow.appendChild(tdIn);
      const out = [document.createElement("td"), document.createElement("td")];
      out[0].className = "value"; out[1].className = "";
      const tdEx = document.createElement("td"); tdEx.textContent = fmtG(exact, 4);
      trow.appendChild(out[0]); trow.appendChild(tdEx); trow.appendChild(out[1]);
      out[1].classList.add("error");
      const tdTheirs = document.createElement("td");
      tdTheirs.className = "reveal";
      tdTheirs.textContent = fx(mm, 1) + "; " + (err === null ? "—" : fx(err, 2));
      trow.appendChild(tdTheirs);
      input.addEventListener("input", () => { checkRow(row, input, out); out[1].classList.add("error"); });
      body.appendChild(trow);
    });
  }
  checkSel.addEventListener("change", drawCheck);
  $("check-reveal").addEventListener("change", () => $("check").classList.toggle("revealed", $("check-reveal").checked));

  // -- the angle: the slider in the turn from position 0 ------------------------------------------------------------
  const slider = $("phi");
  slider.min = "0";
  slider.max = String(r3(turnOf(G.phi[order[N - 1]])));
  slider.step = "any";
  let timer = null;
  function show(i, keepReturn) {
    index = i;
    if (!keepReturn && returnTo !== null) { returnTo = null; updateReturn(); }
    const turn = turnOf(G.phi[i]);
    slider.value = String(turn);
    slider.setAttribute("data-index", String(i));
    slider.setAttribute("aria-valuetext", fx(turn, 1) + "°, φ = " + fx(G.phi[i], 1) + "°");
    const lab = labKey[i];
    $("turn-value").textContent = W().turn + ": " + fx(turn, 1) + "°";
    $("turn-value").setAttribute("data-turn", String(turn));
    $("phi-value").textContent = "φ = " + fx(G.phi[i], 2) + "°";
    $("phi-value").setAttribute("data-phi", String(G.phi[i]));
    $("lab-now").textContent = lab && lab.index !== null ? W().lab + " " + lab.index : "";
    document.querySelectorAll("#lab-positions button").forEach((b) => {
      const on = !!lab && b.getAttribute("data-key") === String(lab.key);
      b.className = on ? "current" : "";
      b.setAttribute("aria-pressed", on ? "true" : "false");
    });
    drawMechanism(i);
    drawPlan("velocity", i);
    drawPlan("acceleration", i);
    updateTable(i);
    updateWarnings(i);
    moveCursor();
  }
  const stepAngle = (d) => show(order[(rank[index] + d + N) % N]);
  const labs = D.positions.filter((p) => p.index !== null).sort((a, b) => turnOf(a.phi) - turnOf(b.phi));
  const home = () => show(nearest((labs[0] || D.positions[0]).phi));
  const end = () => show(nearest((labs[labs.length - 1] || D.positions[D.positions.length - 1]).phi));
  slider.addEventListener("input", () => show(nearestTurn(parseFloat(slider.value))));
  slider.addEventListener("keydown", (ev) => {
    const keys = { ArrowRight: 1, ArrowUp: 1, ArrowLeft: -1, ArrowDown: -1 };
    if (ev.key in keys) { ev.preventDefault(); stepAngle(keys[ev.key]); }
    else if (ev.key === "Home") { ev.preventDefault(); home(); }
    else if (ev.key === "End") { ev.preventDefault(); end(); }
    else if (ev.key === "PageUp" || ev.key === "PageDown") { ev.preventDefault(); stepAngle((ev.key === "PageUp" ? 1 : -1) * Math.max(1, Math.round(10 / D.step))); }
  });
  $("next").addEventListener("click", () => stepAngle(1));
  $("prev").addEventListener("click", () => stepAngle(-1));
  function play() {
    if (timer) { clearInterval(timer); timer = null; }
    else {
      const speed = parseFloat($("speed").value) || 1;       // 1×: 25 grid steps a second
      const per = speed >= 1 ? Math.round(speed) : 1;
      timer = setInterval(() => stepAngle(per), speed >= 1 ? 40 : 40 / speed);
    }
    playWords();
  }
  function playWords() { $("play").textContent = timer ? W().pause : W().play; $("play").setAttribute("aria-pressed", timer ? "true" : "false"); }
  $("play").addEventListener("click", play);
  $("speed").addEventListener("change", () => { if (timer) { play(); play(); } });
  D.positions.forEach((p) => {
    const b = document.createElement("button");
    b.type = "button";
    b.setAttribute("data-key", String(p.key));
    b.textContent = p.index !== null ? String(p.index) : fx(p.phi, 1) + "°";
    b.addEventListener("click", () => {
      show(nearest(p.phi));
      if (current) {           // the replay follows: the same kind of plan at this position
        const k = D.records.findIndex((r) => r.key === p.key && r.kind === current.kind);
        const any = k >= 0 ? k : D.records.findIndex((r) => r.key === p.key);
        if (any >= 0) choose(any, false);
      }
      if (checkKeys.indexOf(String(p.key)) >= 0) { checkSel.value = String(p.key); drawCheck(); }
    });
    $("lab-positions").appendChild(b);
  });
  $("per-angle").addEventListener("change", () => {
    ["velocity", "acceleration"].forEach((k) => { planZ[k].k = 1; planZ[k].cx = 0.5; planZ[k].cy = 0.5; planZ[k].fit(turnBox[k], 28); });
    show(index, true);
  });
  document.addEventListener("keydown", (ev) => {
    const t = ev.target, tag = t && t.tagName;
    if (ev.altKey || ev.ctrlKey || ev.metaKey) return;
    if (tag === "INPUT" && t.type !== "range" && t.type !== "checkbox") return;
    if (tag === "SELECT" || tag === "TEXTAREA") return;
    const inReplay = t && t.closest && t.closest("#replay-section");
    if (ev.key === " " || ev.key === "Spacebar") {
      if (tag === "BUTTON" || (tag === "INPUT" && t.type === "checkbox")) return;   // Space presses a button, ticks a checkbox
      ev.preventDefault(); play(); return;
    }
    if (t === slider) return;                 // the slider's own keys (above)
    if (inReplay) {
      if (ev.key === "ArrowRight") { ev.preventDefault(); stepBy(1); }
      else if (ev.key === "ArrowLeft") { ev.preventDefault(); stepBy(-1); }
      else if (ev.key === "Home") { ev.preventDefault(); stepNo = 0; showStep(); }
      else if (ev.key === "End") { ev.preventDefault(); stepNo = current.steps.length - 1; showStep(); }
      return;
    }
    if (ev.key === "ArrowRight") { ev.preventDefault(); stepAngle(1); }
    else if (ev.key === "ArrowLeft") { ev.preventDefault(); stepAngle(-1); }
    else if (ev.key === "Home") { ev.preventDefault(); home(); }
    else if (ev.key === "End") { ev.preventDefault(); end(); }
  });

  // -- the words of the page, in either language ------------------------------------------------------------------
  function words() {
    const w = W();
    document.documentElement.lang = lang;
    document.title = tr(D.title) + " — graphplan";
    $("title").textContent = tr(D.title);
    setMarkup($("facts"), w.structure + D.structure + fill(w.facts, { w: fmtG(D.omega1, 5), p: fx(D.phi0, 2) }));
    document.querySelectorAll("#langs button").forEach((b) => b.setAttribute("aria-pressed", b.getAttribute("data-lang") === lang ? "true" : "false"));
    $("langs").setAttribute("aria-label", w.langs);
    playWords();
    $("play").setAttribute("aria-label", w.playName);
    $("speed-label").textContent = w.speed;
    const sp = $("speed"), was = sp.value || "1";
    sp.textContent = "";
    ["0.25", "0.5", "1", "2", "4"].forEach((v) => { const o = document.createElement("option"); o.value = v; o.textContent = dec(v) + "×"; sp.appendChild(o); });
    sp.value = was;
    $("prev").setAttribute("aria-label", w.prev);
    $("next").setAttribute("aria-label", w.next);
    slider.setAttribute("aria-label", w.slider);
    $("lab-positions").setAttribute("aria-label", w.labs);
    document.querySelectorAll("#lab-positions button").forEach((b) => {
      const p = D.positions.find((q) => String(q.key) === b.getAttribute("data-key"));
      b.setAttribute("aria-label", (p.index !== null ? w.lab + " " + p.index + ", " : "") + "φ = " + fx(p.phi, 2) + "°");
      b.title = b.getAttribute("aria-label");
    });
    $("per-angle-label").textContent = w.perAngle;
    setMarkup($("cap-mech"), w.mech + fmtG(muL, 4) + " " + unit("m/mm"));
    planCaption("velocity", planMu.velocity);
    planCaption("acceleration", planMu.acceleration);
    $("mech").setAttribute("aria-label", $("cap-mech").textContent + "; " + w.zoomKeys);
    $("zoom-note").textContent = w.zoom;
    $("cap-values").textContent = w.values;
    $("values").querySelector("thead").innerHTML = "";
    const hr = document.createElement("tr");
    [w.q, w.graphical, w.exact, w.error].forEach((h) => { const th = document.createElement("th"); th.textContent = h; hr.appendChild(th); });
    $("values").querySelector("thead").appendChild(hr);
    $("values-note").textContent = fill(w.note, { p: dec(String(D.precision)) });
    $("cap-warnings").textContent = w.warnings;
    $("cap-all").textContent = w.all;
    allWarnings();
    $("cap-replay").textContent = w.replay;
    sel.setAttribute("aria-label", w.plan);
    const chosen = sel.value;
    sel.textContent = "";
    D.records.forEach((r, k) => { const o = document.createElement("option"); o.value = String(k); o.textContent = planName(r); sel.appendChild(o); });
    if (chosen) sel.value = chosen;
    $("step-back").textContent = w.back;
    $("step-next").textContent = w.forward;
    $("step-back").setAttribute("aria-label", w.backName);
    $("step-next").setAttribute("aria-label", w.forwardName);
    $("step-first").setAttribute("aria-label", w.first);
    $("step-last").setAttribute("aria-label", w.last);
    $("replay").setAttribute("aria-label", w.replay);
    $("cap-legend").textContent = w.legend;
    const dl = $("legend");
    dl.textContent = "";
    w.symbols.forEach(([s, d]) => { const dt = document.createElement("dt"); setMarkup(dt, s); const dd = document.createElement("dd"); setMarkup(dd, d); dl.appendChild(dt); dl.appendChild(dd); });
    $("cap-check").textContent = w.check;
    $("check-note").textContent = w.checkNote;
    $("check-position-label").textContent = w.checkAt;
    $("check-reveal-label").textContent = w.reveal;
    const ck = checkSel.value;
    checkSel.textContent = "";
    checkKeys.forEach((k) => {
      const p = D.positions.find((q) => String(q.key) === k);
      const o = document.createElement("option");
      o.value = k;
      o.textContent = p && p.index !== null ? String(p.index) : "φ = " + fx(p ? p.phi : 0, 1) + "°";
      checkSel.appendChild(o);
    });
    if (ck) checkSel.value = ck;
    $("check-section").hidden = !checkKeys.length;
    $("cap-diagrams").textContent = w.diagrams;
    $("diagrams").setAttribute("aria-label", w.diagrams);
    $("footer").textContent = w.footer;
    const o = D.open || {};
    const at = o.index !== null && o.index !== undefined ? fill(w.atPosition, { k: String(o.index) }) : "φ = " + fx(o.phi || 0, 1) + "°";
    $("open-note").textContent = o.why === "accel" ? fill(w.openAccel, { at: at, still: o.still0 ? w.still0 : "" })
      : o.why === "still" ? fill(w.openStill, { at: at, still: w.still0 }) : "";
    $("open-note").hidden = !o.why;
  }
  function setLanguage(l) {
    lang = l;
    const keep = [current ? D.records.indexOf(current) : -1, stepNo];
    words();
    drawDiagrams();
    drawCheck();
    if (keep[0] >= 0) { const r = returnTo; choose(keep[0], false); returnTo = r; updateReturn(); stepNo = keep[1]; showStep(); }
    show(index, true);
  }
  document.querySelectorAll("#langs button").forEach((b) => b.addEventListener("click", () => setLanguage(b.getAttribute("data-lang"))));

  // -- start: every drawing fitted to its panel, refitted when the window changes -------------------------------------
  function fitAll() {
    mechZ.fit(mechBox, 30);
    ["velocity", "acceleration"].forEach((k) => planZ[k].fit($("per-angle").checked ? angleBox(k, index) : turnBox[k], 28));
    if (current) { const box = [0, 0, 0, 0]; recordBox(current, box); replayZ.fit(box, 30); rmechZ.fit(mechBox, 20); }
  }
  words();
  drawDiagrams();
  drawCheck();
  fitAll();
  const firstAccel = D.records.findIndex((r) => r.kind === "acceleration");
  choose(firstAccel >= 0 ? firstAccel : 0, false);
  show(index, true);
  let resizeTimer = null;
  window.addEventListener("resize", () => {
    clearTimeout(resizeTimer);
    resizeTimer = setTimeout(() => { fitAll(); drawDiagrams(); show(index, true); showStep(); }, 60);
  });
  window.graphplanExplorer = { show: show, nearest: nearest, turnOf: turnOf, phi: G.phi, records: D.records,
    choose: (k) => choose(k, true), step: () => stepNo, setLanguage: setLanguage };
})();
