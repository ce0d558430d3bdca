"""Refusals of a teacher's and a student's tables and of the web server speak the reader's language:
Ukrainian by default, English with --lang en / ?lang=en or a base scene's (a key's scene's) lang = "en";
each one line, exit 2 (HTTP 422), no traceback, nothing written. The expected words are the lab's
own for each kind of mistake (the row, the column, the value as typed) — read from the catalogue's
meaning, not from the program's output."""
from __future__ import annotations

import json
import re
from pathlib import Path

import pytest

from conftest import ROOT
from fuzz_scenes import check_run, run

EXAMPLES = ROOT / "examples"
CYRILLIC = re.compile(r"[А-Яа-яІіЇїЄєҐґ]")


def scenes(folder: Path) -> None:
    """base_uk.toml (no lang: Ukrainian) and base_en.toml (lang = "en") — the example crank-slider."""
    text = (EXAMPLES / "crank_slider.toml").read_text(encoding="utf-8")
    text = "\n".join(line for line in text.splitlines() if not line.startswith("lang"))
    (folder / "base_uk.toml").write_text(text + "\n", encoding="utf-8")
    (folder / "base_en.toml").write_text('lang = "en"\n' + text + "\n", encoding="utf-8")


def one_line(argv: list[str], out_dir: Path | None = None) -> str:
    code, out, err = run([str(a) for a in argv])
    check_run([str(a) for a in argv], code, out, err)
    assert code == 2 and out == "" and "Traceback" not in err, (argv, code, err)
    if out_dir is not None:
        assert not out_dir.exists() and not list(out_dir.parent.glob(f".{out_dir.name}.part")), "a partial key set"
    return err.strip()


def speaks(line: str, lang: str) -> None:
    """Ukrainian: Cyrillic words; English: none (the file names here are Latin)."""
    assert bool(CYRILLIC.search(line)) == (lang == "uk"), (lang, line)


# a bad table → the words each language's line names (row, column, the value as typed)
VARIANT_TABLES = {
    "a bad number": ("variant;r;rpm\nv1;0,05;2x00\n", ["3", "rpm", "'2x00'"], ["рядок", "стовпець", "не число"],
                     ["line", "column", "not a number"]),
    "no variant column": ("r;rpm\n0,05;2800\n", ["variant"], ["потрібен стовпець"], ["needs a 'variant' column"]),
    "an unknown column": ("variant;r;rodd\nv1;0,05;3\n", ["'rodd'", "v1"], ["не ім'я з [params]"],
                          ["not a [params] name"]),
    "a variant twice": ("variant;r\nv1;0,05\nv1;0,06\n", ["'v1'", "4"], ["записано двічі"], ["appears twice"]),
    "a decimal comma split": ("variant,r\nv1,0,05\n", ["3", "3", "2"], ["клітинок", "десяткова кома"],
                              ["cells for", "decimal comma"]),
}


@pytest.mark.parametrize("lang", ["uk", "en"])
@pytest.mark.parametrize("kind", list(VARIANT_TABLES))
def test_a_bad_variant_table_is_one_line_in_the_base_scene_s_language(tmp_path, kind, lang):
    scenes(tmp_path)
    text, both, uk, en = VARIANT_TABLES[kind]
    table = tmp_path / "v.csv"
    table.write_text(f"# base = base_{lang}.toml\n{text}", encoding="utf-8")
    line = one_line(["key", table, "-o", tmp_path / "keys", "--quiet", "--no-pdf"], tmp_path / "keys")
    assert line.startswith(f"graphplan: {table}: "), line
    for w in both + (uk if lang == "uk" else en):
        assert w in line, (w, line)
    speaks(line.removeprefix(f"graphplan: {table}: "), lang)


@pytest.mark.parametrize("lang", ["uk", "en"])
def test_a_variant_table_in_cp1251_is_one_line_naming_the_encoding(tmp_path, lang):
    scenes(tmp_path)
    table = tmp_path / "v.csv"
    table.write_bytes(f"# base = base_{lang}.toml\nvariant;student\nv1;".encode() + "Петренко\n".encode("cp1251"))
    line = one_line(["key", table, "-o", tmp_path / "keys", "--quiet"], tmp_path / "keys")
    assert "UTF-8" in line and ("кодуванні" in line if lang == "uk" else "save the file as" in line), line
    speaks(line.removeprefix(f"graphplan: {table}: "), lang)


def test_lang_on_the_command_line_outranks_the_base_scene_s(tmp_path):
    scenes(tmp_path)
    table = tmp_path / "v.csv"
    table.write_text("# base = base_uk.toml\nvariant;r;rpm\nv1;0,05;2x00\n", encoding="utf-8")
    line = one_line(["key", table, "-o", tmp_path / "keys", "--lang", "en"], tmp_path / "keys")
    assert "line 3, column rpm: '2x00': not a number" in line, line


# -- students' tables: the language of --lang, else of the key's scene ------------------------------------

STUDENT_TABLES = {
    "a missing column": ("variant,position,quantity\n01,1,v_B\n", ["'value'"], ["бракує"], ["missing"]),
    "a bad number": ("variant;position;quantity;value\n01;1;v_B;7_2\n", ["2", "'7_2'", "(", "4)"],
                     ["рядок", "стовпець", "без «_»"], ["line", "column", "without '_'"]),
    "an unclosed quote": ('variant,position,quantity,value\n01,1,v_B,"7.2\n', ["2"], ["лапки не закрито"],
                          ["quote is not closed"]),
}


@pytest.fixture()
def key_json(tmp_path):
    """A key as `check` reads it (its format and variant; a scene whose lang the test sets)."""
    def make(lang: str | None) -> Path:
        scene = {"lang": lang} if lang else {}
        path = tmp_path / f"key_{lang}.json"
        path.write_text(json.dumps({"format": "graphplan-key/1", "variant": "01", "scene": scene}), encoding="utf-8")
        return path
    return make


@pytest.mark.parametrize("lang", ["uk", "en"])
@pytest.mark.parametrize("kind", list(STUDENT_TABLES))
def test_a_bad_student_table_is_one_line_in_the_key_scene_s_language(tmp_path, key_json, kind, lang):
    text, both, uk, en = STUDENT_TABLES[kind]
    student = tmp_path / "student.csv"
    student.write_text(text, encoding="utf-8")
    line = one_line(["check", key_json("en" if lang == "en" else None), student])
    for w in both + (uk if lang == "uk" else en):
        assert w in line, (w, line)
    speaks(line.removeprefix(f"graphplan: {student}: "), lang)
    assert one_line(["check", key_json(None), student, "--lang", lang]) == line     # --lang says the same


def test_a_file_that_is_no_key_is_one_line_in_either_language(tmp_path):
    bad = tmp_path / "key.json"
    bad.write_text('{"format": "other/1"}', encoding="utf-8")
    student = tmp_path / "s.csv"
    student.write_text("variant,position,quantity,value\n01,1,v_B,1\n", encoding="utf-8")
    assert "це не ключ graphplan (формат 'other/1'" in one_line(["check", bad, student])
    assert "not a graphplan key (format 'other/1'" in one_line(["check", bad, student, "--lang", "en"])


# -- serve's options ---------------------------------------------------------------------------------------

@pytest.mark.parametrize("argv, uk, en", [
    (["--port", "70000"], "--port: має бути цілим числом від 1 до 65535, задано 70000",
     "--port: must be a whole number from 1 to 65535, got 70000"),
    (["--workers", "0"], "--workers: має бути цілим числом від 1 до 16", "--workers: must be a whole number from 1 to 16"),
    (["--timeout", "0.5"], "--timeout: має бути від 1 до 3600 с, задано 0.5", "--timeout: must be from 1 to 3600 s, got 0.5"),
])
def test_serve_s_options_are_one_line_in_either_language(argv, uk, en):
    assert uk in one_line(["serve", *argv])
    assert en in one_line(["serve", *argv, "--lang", "en"])


# -- the loader's refusal of a rod hung on a sliding link's point -------------------------------------------

def yoke_driving_a_rocker(folder: Path, lang: str, as_joint: bool) -> Path:
    """A Scotch yoke whose yoke drives a rocker ED through a rod CD hung at C: C written as a point of
    the yoke (refused), or as the yoke's own joint (its origin)."""
    from graphplan.web.templates import scene_toml
    text = scene_toml({"template": "scotch_yoke", "values": {}})
    text = text.replace("O = [0, 0]\n", "O = [0, 0]\nE = [0.35, 0.15]\n").replace(
        "[positions]", '[[link]]\nname = "CD"\nnumber = 4\njoints = ["C", "D"]\nlength = 0.3\n\n'
                       '[[link]]\nname = "ED"\nnumber = 5\njoints = ["E", "D"]\nlength = 0.2\n\n[positions]')
    if as_joint:
        text = text.replace('joints = []\nref = "B"', 'joints = ["C"]').replace('point = "B"', 'point = "C"')
    else:
        text = text.replace("points = { S3 = [0, 0] }", "points = { S3 = [0, 0], C = [0.05, 0] }")
    path = folder / f"yoke_{lang}_{as_joint}.toml"
    path.write_text((f'lang = "{lang}"\n' if lang == "en" else "") + text, encoding="utf-8")
    return path


@pytest.mark.parametrize("lang", ["uk", "en"])
def test_a_rod_on_a_yoke_s_point_is_told_how_to_write_it_and_that_way_is_accepted(tmp_path, lang):
    line = one_line(["analyze", yoke_driving_a_rocker(tmp_path, lang, False), "--positions", "4"])
    said = {"uk": ["шарнір 'C'", "ланки yoke", "ковзає по напрямній", 'joints = ["C"]'],
            "en": ["joint 'C'", "link yoke", "slides on a guide", 'joints = ["C"]']}[lang]
    assert all(w in line for w in said), line
    code, out, err = run(["analyze", str(yoke_driving_a_rocker(tmp_path, lang, True)), "--positions", "4", "--json"])
    assert code == 0, err
    doc = json.loads(out)
    d = [p["points"]["D"] for p in doc["positions"]]
    e = complex(0.35, 0.15)
    assert all(abs(complex(p["x"], p["y"]) - e) == pytest.approx(0.2, rel=1e-9) for p in d)   # the rocker's length


# -- the web server: the request's ?lang=, else the scene's ---------------------------------------------------

starlette = pytest.importorskip("starlette")
pytest.importorskip("multipart")


@pytest.fixture
def client(web):
    """The worker's web app in the test client (conftest's ``web_client``, one for the worker)."""
    return web


def refusal(r, status: int = 422) -> str:
    assert r.status_code == status, (r.status_code, r.text[:300])
    doc = r.json()
    assert list(doc) == ["error"] and "\n" not in doc["error"] and "Traceback" not in doc["error"]
    return doc["error"]


@pytest.mark.parametrize("lang", ["uk", "en"])
def test_http_refusals_speak_the_request_s_language(client, lang):
    crank = (EXAMPLES / "crank_slider.toml").read_text(encoding="utf-8")
    lines = [
        refusal(client.post(f"/api/toml?lang={lang}", json={"template": "four_bar", "values": {"l2": "abc"}})),
        refusal(client.post(f"/api/sheet?type=exe&lang={lang}", content=crank.encode())),
        refusal(client.post(f"/api/scene/preview?phi=1e9&lang={lang}", content=crank.encode())),
        refusal(client.post(f"/api/scene/check?lang={lang}", content=b"\xff\xfe")),
        refusal(client.get(f"/api/key/{'0' * 24}?lang={lang}"), 404),
        refusal(client.post(f"/api/check?lang={lang}", content=b"x", headers={"content-type": "text/plain"})),
    ]
    assert lines[0].startswith("form: l2: 'abc'") and lines[1].startswith("-o sheet.exe: ")
    assert lines[2].startswith("--phi: ") and "1e+06" in lines[2] and lines[3].startswith("scene.toml: ")
    for line in lines:
        speaks(re.sub(r"multipart/form-data|'key'|'student'|\S+\.(json|csv|toml)", "", line), lang)


@pytest.mark.parametrize("lang", ["uk", "en"])
def test_a_teacher_s_bad_tables_over_http_speak_the_base_scene_s_language(client, tmp_path, lang):
    scenes(tmp_path)
    base = (tmp_path / f"base_{lang}.toml").read_bytes()
    line = refusal(client.post("/api/key", files={"variants": ("v.csv", b"r;rpm\n0,05;2800\n"), "base": ("b.toml", base)}))
    assert line == {"uk": "variants.csv: таблиці потрібен стовпець variant",
                    "en": "variants.csv: the table needs a 'variant' column"}[lang]
    key = json.dumps({"format": "graphplan-key/1", "variant": "01", "scene": {"lang": lang} if lang == "en" else {}})
    line = refusal(client.post("/api/check", files={"key": ("key.json", key), "student": ("s.csv", "variant,position\n01,1\n01,x,3\n")}))
    assert line.startswith("student.csv: ") and ("рядок 3" in line if lang == "uk" else "line 3" in line), line
    speaks(line.removeprefix("student.csv: "), lang)


@pytest.mark.parametrize("lang", ["uk", "en"])
def test_serve_on_a_port_in_use_is_one_line_before_it_prints_an_address(lang):
    import socket
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        s.listen()
        port = s.getsockname()[1]
        line = one_line(["serve", "--port", str(port), "--lang", lang])
    assert f"127.0.0.1:{port}" in line and "--port" in line and "http://" not in line, line
    speaks(line, lang)
