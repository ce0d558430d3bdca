// graphplan serve: the page. Every number comes from the server (one solver); this file only
// builds the forms, sends the scene and shows what comes back.
"use strict";

const WORDS = {
  uk: {
    title: "graphplan — графічні методи ТММ", student: "Студент", teacher: "Викладач", language: "Мова",
    "student part": "Механізм студента", template: "Схема", "or upload": "або завантажте сцену TOML",
    values: "Значення варіанта", toml: "Сцена (TOML)", "crank angle": "Кут кривошипа",
    "branch help": "Два складання: натисніть на те, яке потрібне.", "branch reset": "Обрати складання знову",
    downloads: "Завантажити", sheets: "Аркуші", kinematics: "кінематика", forces: "сили", dynamics: "динаміка",
    cam: "кулачок", gears: "зубчасті механізми", format: "Формат", "file type": "Файл", "sheet language": "Мова аркуша",
    "download sheets": "Аркуші", "download toml": "TOML", "download view": "Інтерактивна сторінка",
    "download tables": "Таблиці CSV", "teacher part": "Ключі й оцінювання", keys: "Ключі групи",
    variants: "Таблиця варіантів (CSV)", base: "Базова сцена (TOML)", "base current": "або сцена зі сторінки студента",
    "make keys": "Скласти ключі", grading: "Оцінювання", "key file": "Ключ (key.json або zip ключів)",
    students: "Таблиця студента (CSV)", grade: "Оцінити", "grades csv": "Оцінки CSV",
    footer: "Усі обчислення — той самий graphplan, що й у командному рядку.",
    chosen: "Обране складання", working: "Обчислення:", ready: "Готово: ", uploaded: "Сцена з файла",
    "no file": "Оберіть файл", "keys progress": "Варіантів готово: ", "keys done": "Ключі готові: ",
    passed: "зараховано", failed: "не зараховано", rows: "рядків", assembly: "складання",
    "assembly pick": "Обрати складання", default: "типове",
    "default said": "Не обрано, тож аркуші креслять типове",
    "no default": "Типове складання (без [branch]: усі +1) не складається — оберіть складання",
    uploaded_mode: "поля шаблону до неї не застосовуються; щоб повернутися до них, оберіть схему",
    retry: "повторіть за", s: "с", "sheet of": "аркуш", "sheets of": "аркуші", explorer: "інтерактивна сторінка",
    tables: "таблиці CSV", "slow hint": "аркуш креслиться до хвилини, коли сервер зайнятий — довше",
    "lang uk": "українська", "lang en": "English",
  },
  en: {
    title: "graphplan — graphical methods of TMM", student: "Student", teacher: "Teacher", language: "Language",
    "student part": "The student's mechanism", template: "Scheme", "or upload": "or upload a TOML scene",
    values: "The variant's values", toml: "Scene (TOML)", "crank angle": "Crank angle",
    "branch help": "Two assemblies: click the one you need.", "branch reset": "Choose the assembly again",
    downloads: "Download", sheets: "Sheets", kinematics: "kinematics", forces: "forces", dynamics: "dynamics",
    cam: "cam", gears: "gears", format: "Format", "file type": "File", "sheet language": "Sheet language",
    "download sheets": "Sheets", "download toml": "TOML", "download view": "Interactive explorer",
    "download tables": "Tables CSV", "teacher part": "Keys and grading", keys: "The group's keys",
    variants: "Variants table (CSV)", base: "Base scene (TOML)", "base current": "or the scene of the student's part",
    "make keys": "Make the keys", grading: "Grading", "key file": "Key (key.json or the keys' zip)",
    students: "Student's table (CSV)", grade: "Grade", "grades csv": "Grades CSV",
    footer: "Every number is the same graphplan as on the command line.",
    chosen: "Assembly chosen", working: "Working on", ready: "Ready: ", uploaded: "The scene from",
    "no file": "Choose a file", "keys progress": "Variants done: ", "keys done": "The keys are ready: ",
    passed: "passed", failed: "failed", rows: "rows", assembly: "assembly",
    "assembly pick": "Choose assembly", default: "the default",
    "default said": "None chosen, so the sheets draw the default,",
    "no default": "The default assembly (no [branch]: all +1) does not assemble — choose one",
    uploaded_mode: "the template's fields do not apply to it; choose a scheme to return to them",
    retry: "try again in", s: "s", explorer: "the explorer",
    tables: "the tables CSV", "slow hint": "a sheet takes up to a minute, longer when the server is busy",
    "lang uk": "українська", "lang en": "English",
  },
};

const $ = (id) => document.getElementById(id);
const state = {
  lang: "uk", templates: [], template: null, values: {}, branch: {}, mode: "template", toml: "",
  assemblies: [], seq: 0, timer: null, grades: null, kind: "lever",
};

function t(key) { return (WORDS[state.lang] || WORDS.uk)[key] || WORDS.en[key] || key; }

function translate() {
  document.documentElement.lang = state.lang;
  document.querySelectorAll("[data-t]").forEach((el) => { el.textContent = t(el.dataset.t); });
  document.title = t("title");
  $("sheet-lang").querySelectorAll("option").forEach((o) => { o.textContent = t("lang " + o.value); });
  renderTemplates();
  sayUploaded();
  $("dl-status").textContent = "";               // said in the other language: not left mixed
  $("dl-error").textContent = "";
  if (state.grades) showGrades(state.grades);
  if (state.assemblies && state.assemblies.length === 2) showAssemblies(null, state.assemblies);   // the buttons' words too
}

function sayUploaded() {
  // an uploaded scene: its name where the template's fields were, and how to return to them
  const said = $("upload-said");
  said.hidden = state.mode === "template";
  said.textContent = state.mode === "template" ? "" :
    `${t("uploaded")} ${state.uploaded || "TOML"}: ${t("uploaded_mode")}.`;
  $("fields").hidden = state.mode !== "template";
}

// -- requests ---------------------------------------------------------------------------------------

async function post(path, body, type) {
  const headers = {};
  if (type) headers["Content-Type"] = type;
  const r = await fetch(path, { method: "POST", body, headers, credentials: "same-origin" });
  if (!r.ok) {
    let line = r.status + " " + r.statusText;
    try { line = (await r.json()).error || line; } catch (e) { /* not JSON */ }
    const err = new Error(line);
    err.status = r.status;
    err.retry = r.headers.get("Retry-After");
    err.stem = r.headers.get("X-File-Stem");
    throw err;
  }
  return r;
}

function save(blob, name) {
  const a = document.createElement("a");
  a.href = URL.createObjectURL(blob);
  a.download = name;
  document.body.appendChild(a);
  a.click();
  setTimeout(() => { URL.revokeObjectURL(a.href); a.remove(); }, 2000);
}

function filename(r, fallback) {
  const m = /filename="([^"]+)"/.exec(r.headers.get("Content-Disposition") || "");
  return m ? m[1] : fallback;
}

// -- the template's form ----------------------------------------------------------------------------

function symbol(text) {
  // "l_OA" → l with the subscript OA; "λ = l_BC/l_OB" keeps its words
  const span = document.createElement("span");
  span.className = "sym";
  text.split(/(\s+|\/|=)/).forEach((part) => {
    const m = /^([^_]*)_(.+)$/.exec(part);
    if (m) {
      span.appendChild(document.createTextNode(m[1]));
      const sub = document.createElement("sub");
      sub.textContent = m[2];
      span.appendChild(sub);
    } else {
      span.appendChild(document.createTextNode(part));
    }
  });
  return span;
}

const UNITS = { uk: { m: "м", rpm: "об/хв", kg: "кг", N: "Н", deg: "°", "kg/m": "кг/м", "rad/s": "рад/с" },
                en: { m: "m", rpm: "rpm", kg: "kg", N: "N", deg: "°", "kg/m": "kg/m", "rad/s": "rad/s" } };

const CHOICES = {
  uk: { ccw: "проти год. стрілки", cw: "за год. стрілкою", cosine: "косинусоїдальний",
        cycloidal: "синусоїдальний (циклоїдальний)", parabolic: "параболічний", trapezoidal: "трапецеїдальний",
        linear: "лінійний", working: "робочий", idle: "холостий", both: "обидва" },
  en: { ccw: "counter-clockwise", cw: "clockwise", cosine: "cosine", cycloidal: "cycloidal (sine)",
        parabolic: "parabolic", trapezoidal: "trapezoidal", linear: "linear", working: "working", idle: "idle",
        both: "both" },
};

function renderTemplates() {
  const sel = $("template");
  const chosen = sel.value || (state.template && state.template.id);
  sel.textContent = "";
  state.templates.forEach((tp) => {
    const o = document.createElement("option");
    o.value = tp.id;
    o.textContent = tp[state.lang];
    sel.appendChild(o);
  });
  if (chosen && state.mode === "template") sel.value = chosen;
  else if (state.mode !== "template") sel.selectedIndex = -1;
  renderFields();
}

function renderFields() {
  const box = $("fields");
  const legend = box.querySelector("legend");
  box.textContent = "";
  box.appendChild(legend);
  const tp = state.template;
  if (!tp) return;
  tp.fields.forEach((f) => {
    const row = document.createElement("div");
    row.className = "field";
    const id = "f-" + f.key;
    const label = document.createElement("label");
    label.htmlFor = id;
    if (f.symbol) label.appendChild(symbol(f.symbol));
    label.appendChild(document.createTextNode(f[state.lang]));
    let input;
    if (f.choices && f.choices.length) {
      input = document.createElement("select");
      f.choices.forEach((c) => {
        const o = document.createElement("option");
        o.value = c;
        o.textContent = (CHOICES[state.lang] || {})[c] || c;
        input.appendChild(o);
      });
    } else {
      input = document.createElement("input");
      input.type = "text";
      if (typeof f.default === "number") input.inputMode = "decimal";
    }
    input.id = id;
    input.name = f.key;
    input.value = state.values[f.key] !== undefined ? state.values[f.key] : f.default;
    const err = document.createElement("span");
    err.className = "err";
    err.id = id + "-err";
    err.setAttribute("aria-live", "polite");
    input.setAttribute("aria-describedby", err.id);
    input.addEventListener("input", () => { state.values[f.key] = input.value; changed(); });
    input.addEventListener("change", () => { state.values[f.key] = input.value; changed(); });
    const unit = document.createElement("span");
    unit.className = "unit";
    unit.textContent = (UNITS[state.lang] || {})[f.unit] || f.unit;
    if (f.choices && f.choices.length) {                                    // a choice takes the unit's column too
      row.classList.add("choice");
      row.append(label, input, err);
    }
    else row.append(label, input, unit, err);
    box.appendChild(row);
  });
  box.disabled = state.mode !== "template";
  box.hidden = state.mode !== "template";
}

function clearFieldErrors() {
  document.querySelectorAll(".field .err").forEach((e) => { e.textContent = ""; });
  document.querySelectorAll(".field [aria-invalid]").forEach((e) => e.removeAttribute("aria-invalid"));
  $("scene-error").textContent = "";
}

function asUploaded(line) {
  // "scene.toml: …" → "<the student's file>: …" (the server names the scene it was sent by a fixed name)
  return state.mode === "toml" && state.uploaded && line.startsWith("scene.toml:")
    ? state.uploaded + line.slice("scene.toml".length) : line;
}

function showError(line) {
  // "form: r: ... is not a number" → beside the field r; the rest (assembly ranges …) above the preview
  line = asUploaded(line);
  const m = /^form: (\w+):/.exec(line);
  const input = m && $("f-" + m[1]);
  if (input) {
    input.setAttribute("aria-invalid", "true");
    $("f-" + m[1] + "-err").textContent = line.replace(/^form: \w+: /, "");
  } else {
    $("scene-error").textContent = line;     // the server says it in the page's language
  }
  $("preview").classList.add("stale");
}

// -- the scene, its preview -----------------------------------------------------------------------

async function sceneText() {
  if (state.mode === "toml") return withBranch($("toml").value);
  const body = JSON.stringify({ template: state.template.id, values: state.values, branch: state.branch });
  const r = await post(`/api/toml?lang=${state.lang}`, body, "application/json");
  const text = await r.text();
  $("toml").value = text;
  return text;
}

function withBranch(text) {
  // the chosen assembly written into an uploaded scene's [branch] table
  const keys = Object.keys(state.branch);
  if (!keys.length) return text;
  const lines = keys.map((k) => `${k} = ${state.branch[k]}`).join("\n");
  if (/^\[branch\]\s*$/m.test(text)) return text.replace(/^\[branch\]\s*$/m, "[branch]\n" + lines);
  return text.replace(/\s*$/, "\n") + "\n[branch]\n" + lines + "\n";
}

const NARROW = window.matchMedia("(max-width: 820px)");   // app.css's one column
NARROW.addEventListener("change", () => changed());

function changed() {
  clearTimeout(state.timer);
  state.pending = true;
  $("preview").dataset.busy = "1";              // drawing: a test (or a reader) can wait for it
  state.timer = setTimeout(refresh, 150);
}

async function refresh() {
  state.pending = false;
  $("preview").dataset.busy = "1";
  const seq = ++state.seq;
  try {
    await draw(seq);
  } finally {
    if (seq === state.seq && !state.pending) delete $("preview").dataset.busy;
  }
}

async function draw(seq) {
  clearFieldErrors();
  let text;
  try {
    text = await sceneText();
    state.toml = text;
    const phi = $("phi").value;
    const stack = NARROW.matches;     // one column (a phone): the two assemblies one above the other
    const r = await post(`/api/scene/preview?phi=${encodeURIComponent(phi)}&lang=${state.lang}${stack ? "&stack=1" : ""}`,
                         text, "text/plain; charset=utf-8");
    const blob = await r.blob();
    if (seq !== state.seq) return;
    state.stem = [text, r.headers.get("X-File-Stem")];   // the downloads' name: the scene's designation and its fingerprint
    const keys = JSON.parse(decodeURIComponent(r.headers.get("X-Branch-Keys") || "%5B%5D"));
    const asm = JSON.parse(decodeURIComponent(r.headers.get("X-Assemblies") || "%5B%5D"));
    const img = $("preview-img");
    const old = img.src;
    img.src = URL.createObjectURL(blob);
    if (old) URL.revokeObjectURL(old);
    const kind = r.headers.get("X-Scene-Kind") || "lever";
    img.alt = kind === "gears" ? (state.lang === "uk" ? "Зубчасте зачеплення і планетарна передача"
                                                      : "The gear meshing and the planetary train")
      : (state.lang === "uk" ? "Механізм при φ1 = " : "The mechanism at φ1 = ") + phi + "°";
    $("preview").classList.remove("stale");
    $("phi-row").hidden = kind !== "lever";          // a cam's profile, a gear's meshing: no crank angle
    $("dl-view").hidden = kind === "gears";          // the explorer shows levers and cams: a gear scene's was refused after the click
    const offered = (r.headers.get("X-Sheet-Kinds") || (kind === "lever" ? "kinematics" : kind)).split(",");
    offerKinds(offered, kind !== state.kind);        // only the sheets this scene makes; another kind: its first ticked
    state.kind = kind;
    showAssemblies(keys, asm);
  } catch (e) {
    if (seq !== state.seq) return;
    if (e.stem) state.stem = [text, e.stem];
    showError(e.message);
    if (e.status === 422) guessKinds(text);
    if (e.status === 503) setTimeout(changed, 1000 * Number(e.retry || 5));   // busy: ask again
  }
}

function showAssemblies(keys, asm) {
  const box = $("assemblies");
  $("preview").classList.toggle("stacked", NARROW.matches);   // the buttons over the drawings as drawn
  box.textContent = "";
  state.assemblies = asm;
  const two = asm.length === 2;
  $("branch-help").hidden = !two;
  asm.forEach((a, k) => {
    if (!two) return;
    const b = document.createElement("button");
    b.type = "button";
    b.className = "assembly" + (a.error ? " broken" : "");
    b.id = "assembly-" + (k + 1);
    const said = Object.entries(a.branch).map(([p, s]) => `${p} = ${s > 0 ? "+1" : "−1"}`).join(", ");
    const dflt = a.default ? ` (${t("default")})` : "";
    b.setAttribute("aria-label", `${t("assembly pick")} ${k + 1}: [branch] ${said}${dflt}` + (a.error ? ` — ${asUploaded(a.error)}` : ""));
    b.textContent = `${t("assembly")} ${k + 1}${dflt}`;
    if (a.default) b.classList.add("default");
    if (a.error) b.disabled = true;
    b.addEventListener("click", () => {
      Object.assign(state.branch, a.branch);
      sayBranch();
      refresh();
    });
    box.appendChild(b);
  });
  sayBranch();
}

function sayBranch() {
  const entries = Object.entries(state.branch);
  const said = (pairs) => pairs.map(([p, s]) => `${p} = ${s > 0 ? "+1" : "−1"}`).join(", ");
  const asm = state.assemblies || [];
  const k = asm.findIndex((a) => a.default);
  // none chosen while two are drawn: which one the sheets take (the scene's default, [branch] +1)
  $("branch-said").textContent = entries.length ? `${t("chosen")}: [branch] ` + said(entries)
    : asm.length !== 2 ? ""
    : k >= 0 ? `${t("default said")} ${t("assembly")} ${k + 1} ([branch] ${said(Object.entries(asm[k].branch))}).`
    : `${t("no default")}.`;
  $("branch-reset").hidden = !entries.length;
}

// -- downloads ------------------------------------------------------------------------------------

async function download(path, fallback, button, what) {
  // the file asked for; meanwhile what is being made and the seconds it has taken, every second
  $("dl-error").textContent = "";
  button.disabled = true;
  const t0 = Date.now();
  const seconds = () => Math.round((Date.now() - t0) / 1000);
  const tick = () => {
    const s = seconds();
    $("dl-status").textContent = `${t("working")} ${what()}… ${s} ${t("s")}` + (s >= 15 ? ` (${t("slow hint")})` : "");
  };
  tick();
  const clock = setInterval(tick, 1000);
  $("dl-status").dataset.busy = "1";
  try {
    const text = await sceneText();
    const r = await post(path, text, "text/plain; charset=utf-8");
    const name = filename(r, fallback);
    save(await r.blob(), name);
    clearInterval(clock);
    $("dl-status").textContent = `${t("ready")}${name} (${seconds()} ${t("s")})`;
  } catch (e) {
    clearInterval(clock);
    $("dl-status").textContent = "";
    $("dl-error").textContent = asUploaded(e.message) + (e.retry ? ` (${t("retry")} ${e.retry} ${t("s")})` : "");
  } finally {
    clearInterval(clock);
    delete $("dl-status").dataset.busy;
    button.disabled = false;
  }
}

function sheetsSaid() {
  // "the sheet kinematics, A1, PDF" in the page's words
  const kinds = [...document.querySelectorAll("input[name=kind]:checked")].map((c) => t(c.value));
  const which = state.lang === "uk"
    ? `${t(kinds.length > 1 ? "sheets of" : "sheet of")} «${kinds.join(", ")}»`
    : `the ${kinds.join(", ")} ${kinds.length > 1 ? "sheets" : "sheet"}`;
  return `${which}, ${$("format").value}, ${$("type").value.toUpperCase()}`;
}

function sheetPath() {
  const kinds = [...document.querySelectorAll("input[name=kind]:checked")].map((c) => c.value).join(",");
  return `/api/sheet?kind=${encodeURIComponent(kinds)}&format=${$("format").value}&type=${$("type").value}` +
    `&lang=${$("sheet-lang").value}`;
}

// -- the teacher's part -------------------------------------------------------------------------------

async function readFile(input) {
  const f = input.files && input.files[0];
  if (!f) throw new Error(t("no file") + ": " + input.labels[0].textContent);
  return f;
}

function named(line, fixed, input) {
  // "variants.csv: …" → "<the teacher's file>: …" (the server names the uploaded copies by fixed names)
  const f = input.files && input.files[0];
  return f && line.startsWith(fixed + ":") ? f.name + line.slice(fixed.length) : line;
}

async function makeKeys() {
  $("key-error").textContent = "";
  $("key-status").textContent = "";
  const button = $("make-keys");
  const bar = $("key-progress");
  try {
    const fd = new FormData();
    fd.append("variants", await readFile($("variants")), "variants.csv");
    if ($("base-current").checked) {
      fd.append("base", new Blob([await sceneText()], { type: "text/plain" }), "base.toml");
    } else {
      fd.append("base", await readFile($("base")), "base.toml");
    }
    button.disabled = true;
    const r = await post(`/api/key?wait=0&lang=${state.lang}`, fd);
    let job = await r.json();
    bar.hidden = false;
    while (job.state === "running") {
      bar.max = job.total;
      bar.value = job.done;
      $("key-status").textContent = t("keys progress") + `${job.done} / ${job.total}`;
      await new Promise((ok) => setTimeout(ok, 700));
      const s = await fetch(`/api/key/${encodeURIComponent(job.job)}`, { credentials: "same-origin" });
      job = await s.json();
      if (!s.ok) throw new Error(job.error);
    }
    if (job.state !== "done") throw new Error(job.error);
    bar.max = job.total;
    bar.value = job.total;
    const z = await fetch(`/api/key/${encodeURIComponent(job.job)}/zip`, { credentials: "same-origin" });
    if (!z.ok) throw new Error((await z.json()).error);
    const name = filename(z, "keys.zip");      // the base scene's designation and a fingerprint
    save(await z.blob(), name);
    $("key-status").textContent = t("keys done") + name;
  } catch (e) {
    const line = named(e.message, "variants.csv", $("variants"));
    $("key-error").textContent = $("base-current").checked ? line : named(line, "base.toml", $("base"));
  } finally {
    button.disabled = false;
  }
}

async function gradeForm() {
  const fd = new FormData();
  const key = await readFile($("keyfile"));
  fd.append("key", key, key.name.endsWith(".zip") ? "keys.zip" : "key.json");
  fd.append("student", await readFile($("students")), "student.csv");
  return fd;
}

async function grade() {
  $("grade-error").textContent = "";
  try {
    const r = await post(`/api/check?lang=${state.lang}`, await gradeForm());
    showGrades(await r.json());
  } catch (e) {
    $("grade-error").textContent = named(named(e.message, "student.csv", $("students")), "key.json", $("keyfile"));
  }
}

async function gradesCsv() {
  $("grade-error").textContent = "";
  try {
    const r = await post(`/api/check?format=csv&lang=${state.lang}`, await gradeForm());
    save(await r.blob(), "grades.csv");
  } catch (e) {
    $("grade-error").textContent = named(named(e.message, "student.csv", $("students")), "key.json", $("keyfile"));
  }
}

function showGrades(doc) {
  state.grades = doc;
  const cols = ["line", "variant", "position", "quantity", "value", "exact", "error_pct", "tolerance_pct", "status", "note"];
  const heads = state.lang === "uk"
    ? ["рядок", "варіант", "положення", "величина", "значення", "точне", "похибка, %", "допуск, %", "оцінка", "примітка"]
    : ["line", "variant", "position", "quantity", "value", "exact", "error, %", "tolerance, %", "status", "note"];
  const verdict = state.lang === "uk" ? { pass: "зараховано", fail: "не зараховано", unknown: "невідомо" } : {};
  const head = $("grades").tHead;
  const body = $("grades").tBodies[0];
  head.textContent = "";
  body.textContent = "";
  const tr = head.insertRow();
  cols.forEach((c, k) => { const th = document.createElement("th"); th.textContent = heads[k]; th.scope = "col"; tr.appendChild(th); });
  doc.rows.forEach((row) => {
    const r = body.insertRow();
    r.className = row.status;
    cols.forEach((c) => {
      const td = r.insertCell();
      let v = c === "note" && state.lang === "uk" && row.note_uk ? row.note_uk : row[c];
      if (c === "status") v = verdict[v] || v;
      if (typeof v === "number" && !Number.isInteger(v)) v = Number(v.toPrecision(5));
      td.textContent = v === null || v === undefined ? "" : String(v);
      if (["variant", "quantity", "status", "note"].includes(c)) td.className = "l";
    });
  });
  const s = doc.summary;
  $("grade-summary").textContent = `${s.rows} ${t("rows")}: ${s.passed} ${t("passed")}, ${s.failed} ${t("failed")}` +
    (s.pass_pct !== null ? ` (${s.pass_pct} %)` : "");
}

// -- start ------------------------------------------------------------------------------------------

function chooseTemplate(id) {
  state.template = state.templates.find((tp) => tp.id === id) || state.templates[0];
  state.values = {};
  state.branch = {};
  state.mode = "template";
  state.uploaded = "";
  $("dl-status").textContent = "";                 // the previous scene's download said nothing of this one
  $("dl-error").textContent = "";
  renderFields();
  sayUploaded();
  sayBranch();
  const chosen = state.template.id;
  defaultKinds(chosen.startsWith("cam") ? "cam" : chosen.startsWith("gears") ? "gears" : "lever");
  changed();
}

function defaultKinds(kind) {
  // the sheet a scene of this kind has by default (graphplan sheet: kinematics, cam or gears)
  offerKinds([kind === "lever" ? "kinematics" : kind], true);
  state.kind = kind;
}

function guessKinds(text) {
  // a scene the server refused: its sheets guessed from its tables (a [cam], a [gears] or [planetary],
  // else a lever mechanism's kinematics), so that a download says the scene's own fault, not "no [gears]"
  if (typeof text !== "string") return;
  const kind = /^\s*\[cam\]/m.test(text) ? "cam" : /^\s*\[(gears|planetary)\]/m.test(text) ? "gears" : "lever";
  if (kind !== state.kind) defaultKinds(kind);
}

function offerKinds(kinds, fresh) {
  // the sheets' boxes of the kinds the scene makes (the preview's X-Sheet-Kinds), the others hidden
  // and unticked; the first ticked when none is (or the scene is of another kind)
  const boxes = [...document.querySelectorAll("input[name=kind]")];
  boxes.forEach((c) => {
    const shown = kinds.includes(c.value);
    c.closest("label").hidden = !shown;
    if (!shown || fresh) c.checked = false;
  });
  const shown = boxes.filter((c) => kinds.includes(c.value));
  if (shown.length && !shown.some((c) => c.checked)) shown[0].checked = true;
}

function showPart(which) {
  const student = which === "student";
  $("student").hidden = !student;
  $("teacher").hidden = student;
  $("tab-student").setAttribute("aria-pressed", String(student));
  $("tab-teacher").setAttribute("aria-pressed", String(!student));
}

async function start() {
  const asked = new URLSearchParams(location.search).get("lang");
  state.lang = asked === "en" || (!asked && (navigator.language || "").slice(0, 2) === "en") ? "en" : "uk";
  $("lang").value = state.lang;
  $("sheet-lang").value = state.lang;
  const r = await fetch("/api/templates", { credentials: "same-origin" });
  state.templates = await r.json();
  state.template = state.templates[0];
  translate();
  $("lang").addEventListener("change", () => { state.lang = $("lang").value; $("sheet-lang").value = state.lang; translate(); changed(); });
  $("template").addEventListener("change", () => chooseTemplate($("template").value));
  $("upload").addEventListener("change", async () => {
    const f = $("upload").files[0];
    if (!f) return;
    $("toml").value = await f.text();
    state.mode = "toml";
    state.uploaded = f.name;
    state.branch = {};
    $("template").selectedIndex = -1;             // no template: choosing one goes back to the form
    $("fields").disabled = true;
    $("toml-box").open = true;
    $("scene-error").textContent = "";
    $("dl-status").textContent = "";              // "Ready: gears-A1.pdf" was the previous scene's
    $("dl-error").textContent = "";
    sayUploaded();                                // the template's fields hidden: their values are not the scene's
    changed();
  });
  $("toml").addEventListener("input", () => {
    if (state.mode === "template") { state.mode = "toml"; state.uploaded = ""; sayUploaded(); }
    $("fields").disabled = true;
    changed();
  });
  const phi = $("phi"), num = $("phi-num");
  phi.addEventListener("input", () => { num.value = phi.value; changed(); });
  num.addEventListener("input", () => { phi.value = num.value; changed(); });
  $("branch-reset").addEventListener("click", () => { state.branch = {}; sayBranch(); changed(); });
  $("dl-sheet").addEventListener("click", (e) => download(sheetPath(), "sheet", e.currentTarget, sheetsSaid));
  $("dl-view").addEventListener("click", (e) => download(`/api/view?lang=${$("sheet-lang").value}`, "explorer.html",
                                                         e.currentTarget, () => t("explorer")));
  $("dl-tables").addEventListener("click", (e) => download(`/api/tables?lang=${$("sheet-lang").value}`, "tables.zip",
                                                           e.currentTarget, () => t("tables")));
  $("dl-toml").addEventListener("click", async () => {
    try {
      const text = await sceneText();
      const stem = state.stem && state.stem[0] === text && state.stem[1];
      save(new Blob([text], { type: "text/plain" }), (stem || "scene") + ".toml");
    } catch (e) { $("dl-error").textContent = e.message; }
  });
  $("tab-student").addEventListener("click", () => showPart("student"));
  $("tab-teacher").addEventListener("click", () => showPart("teacher"));
  $("make-keys").addEventListener("click", makeKeys);
  $("grade").addEventListener("click", grade);
  $("grade-csv").addEventListener("click", gradesCsv);
  $("scene-form").addEventListener("submit", (e) => { e.preventDefault(); refresh(); });
  refresh();
}

document.addEventListener("DOMContentLoaded", start);
