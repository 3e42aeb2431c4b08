#!/usr/bin/env python3
"""Writes the fuzz corpus of issue 19 into tests/fuzz/corpus/ (manifest.json
and one small input per entry), by mutating the shipped valid files (scenes/,
timelines/, examples/, assets/) and by targeted cases.

Deterministic: a fixed seed, sorted traversals and fixed float formatting, so
rerunning it rewrites the same corpus bit for bit (run_corpus.py --check-generated
and `git diff` show a difference). Run from anywhere: python3 tests/fuzz/generate.py

Manifest entry: name, kind, file (corpus-relative, or null for command lines),
args (placeholders {file} {dir} {src} {out} {corpus}), exit (0 or 2),
contains (substrings that stdout + stderr must hold; {file} is the input's
path), timeout_s, and "open" when the fix lies outside the readers (OPEN.md).
"""
import copy
import json
import os
import random
import shutil
import struct
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
SRC = os.path.normpath(os.path.join(HERE, "..", ".."))
CORPUS = os.path.join(HERE, "corpus")
OUT = CORPUS  # where main() writes; --check writes elsewhere and compares
rng = random.Random(19)
entries = []


def rel(*parts):
    return os.path.join(SRC, *parts)


def load(path):
    with open(rel(path), "rb") as f:
        return json.loads(f.read().decode("utf-8"))


def dump(doc):
    """Compact JSON; RAW markers become literal number text (1e999)."""
    text = json.dumps(doc, separators=(",", ":"), ensure_ascii=False)
    for marker, raw in RAW.items():
        text = text.replace(json.dumps(marker), raw)
    return text + "\n"


RAW = {"__RAW_1e999__": "1e999", "__RAW_-1e999__": "-1e999"}


# Entries whose open item is fixed (OPEN.md says where): they must pass now.
FIXED = {
    "case/coil-1km.json", "cli/plan-max-time-1e308", "cli/plan-sensitivity-1e308", "cli/plan-spacing-1e-300",
    "cli/plan-speed-1e308", "cli/practice-duration-1e9", "cli/practice-duration-4000-record",
    "cli/practice-out-then-option", "scene/default.area-1e9.json", "scene/default.beams-100000.json",
    "scene/default.coil-1km.json", "scene/default.density-1e-300.json", "scene/default.gravity-1e9.json",
    "scene/default.max-push-speed-1e9.json", "scene/default.time-step-1.json", "session/coil-not-in-case.json",
    "session/names-another-case.json", "session/refused-detach-before-push.json",
}


def add(name, kind, content, args, exit_code, contains=(), timeout=20, open_=None, path=None, extra=None):
    """content: str/bytes written to corpus/<kind>/<name> (or `path`), None for no file."""
    entry = {"name": kind + "/" + name, "kind": kind}
    if entry["name"] in FIXED:
        open_ = None
    if content is not None:
        fpath = path or os.path.join(kind, name)
        entry["file"] = fpath
        full = os.path.join(OUT, fpath)
        os.makedirs(os.path.dirname(full), exist_ok=True)
        with open(full, "wb") as f:
            f.write(content.encode("utf-8") if isinstance(content, str) else content)
    else:
        entry["file"] = None
    for p, c in (extra or {}).items():  # companion files (a scene next to its mesh...)
        full = os.path.join(OUT, p)
        os.makedirs(os.path.dirname(full), exist_ok=True)
        with open(full, "wb") as f:
            f.write(c.encode("utf-8") if isinstance(c, str) else c)
    entry["args"] = list(args)
    entry["exit"] = exit_code
    entry["contains"] = list(contains)
    entry["timeout_s"] = timeout
    if open_:
        entry["open"] = open_
    assert entry["name"] not in {e["name"] for e in entries}, entry["name"]
    entries.append(entry)


# ---------------------------------------------------------------- JSON helpers

def seg(k):
    return str(k).replace("~", "~0").replace("/", "~1")


def walk(node, pointer=""):
    """(pointer, value) of every value below the root, in document order."""
    if isinstance(node, dict):
        for k, v in node.items():
            p = pointer + "/" + seg(k)
            yield p, v
            yield from walk(v, p)
    elif isinstance(node, list):
        for i, v in enumerate(node):
            p = pointer + "/" + str(i)
            yield p, v
            yield from walk(v, p)


def parts(pointer):
    return [s.replace("~1", "/").replace("~0", "~") for s in pointer.split("/")[1:]]


def replaced(doc, pointer, value):
    d = copy.deepcopy(doc)
    node = d
    keys = parts(pointer)
    for k in keys[:-1]:
        node = node[int(k)] if isinstance(node, list) else node[k]
    last = keys[-1]
    node[int(last) if isinstance(node, list) else last] = value
    return d


def wrong_type(v):
    if isinstance(v, bool):
        return "yes"
    if isinstance(v, (int, float)):
        return "abc"
    if isinstance(v, str):
        return True  # not a number: "node": "last" also takes 12
    if isinstance(v, list):
        return {}
    if isinstance(v, dict):
        return [] if v else "x"
    return True


def pick(items, n):
    items = list(items)
    if len(items) <= n:
        return items
    return sorted(rng.sample(items, n), key=items.index)


def slug(pointer):
    return pointer.strip("/").replace("/", ".").replace("~1", "_") or "root"


def json_mutations(kind, base_name, doc, args, n_type, n_num, text=None, path_strip="", skip=(), ext=".json",
                   file_path=None, contains_file=True, unknown_keys_ignored=False):
    """Generic mutations of one valid document: wrong types, 1e308, 1e999,
    unknown key, truncations. Each must be refused naming the JSON path."""
    nodes = [(p, v) for p, v in walk(doc) if not any(p.startswith(s) for s in skip)]
    numbers = [(p, v) for p, v in nodes if isinstance(v, (int, float)) and not isinstance(v, bool)]
    fname = lambda tag: file_path(tag) if file_path else None
    for p, v in pick(nodes, n_type):
        shown = p[len(path_strip):] if path_strip and p.startswith(path_strip) else p
        name = base_name + ".type." + slug(p) + ext
        add(name, kind, dump(replaced(doc, p, wrong_type(v))), args, 2,
            (["{file}"] if contains_file else []) + [shown], path=fname(name))
    for i, (p, v) in enumerate(pick(numbers, n_num)):
        shown = p[len(path_strip):] if path_strip and p.startswith(path_strip) else p
        value = ["__RAW_1e999__", 1e308, -1e308][i % 3]
        tag = ["1e999", "1e308", "-1e308"][i % 3]
        name = base_name + "." + tag + "." + slug(p) + ext
        add(name, kind, dump(replaced(doc, p, value)), args, 2, (["{file}"] if contains_file else []) + [shown],
            path=fname(name))
    # An unknown key at the root: a typo must not be silently ignored.
    if isinstance(doc, dict):
        d = dict(doc)
        d["lenght_mm"] = 1
        name = base_name + ".unknown-key" + ext
        if unknown_keys_ignored:  # coil-measurement/1 ignores unknown keys, as the format says
            add(name, kind, dump(d), args, 0, [], path=fname(name))
        else:
            add(name, kind, dump(d), args, 2, (["{file}"] if contains_file else []) + ["/lenght_mm"], path=fname(name))
    if text is not None:
        for frac in (0.0, 0.37, 0.81):
            cut = int(len(text) * frac)
            name = base_name + ".truncated-%d" % cut + ext
            add(name, kind, text[:cut], args, 2, (["{file}"] if contains_file else []) + ["malformed JSON"],
                path=fname(name))


# ---------------------------------------------------------------- scenes

SCENE_RUN = ["run", "{file}", "--headless", "--steps", "2", "--out", "{out}/result.json"]
MESH_UP = "../../../../assets/meshes/"  # from corpus/<kind>/ to assets/meshes


def fix_mesh_paths(doc):
    for o in doc.get("obstacles", []):
        if isinstance(o, dict) and isinstance(o.get("mesh"), str) and o["mesh"].startswith("../assets/meshes/"):
            o["mesh"] = MESH_UP + o["mesh"][len("../assets/meshes/"):]
    return doc


def scenes():
    names = sorted(f for f in os.listdir(rel("scenes")) if f.endswith(".json"))
    for f in names:
        doc = fix_mesh_paths(load("scenes/" + f))
        base = f[:-5]
        static = doc.get("solve") == "static"
        args = ["run", "{file}", "--headless", "--out", "{out}/result.json"] if static else SCENE_RUN
        add(base + ".valid.json", "scene", json.dumps(doc, indent=1) + "\n", args, 0, ["{file}"], timeout=60)
        json_mutations("scene", base, doc, args, 5, 3, text=json.dumps(doc, indent=1), skip=("/description", "/name"))
    d = fix_mesh_paths(load("scenes/default.json"))
    dep = lambda **kw: d  # noqa
    targeted = [
        # (name, pointer, value, expected substring, open reason)
        ("coil-1km", "/deployment/coil/length_mm", 1e6, "/deployment/coil/length_mm",
         "a 1 km coil runs without a word: scene_parse.cpp needs a range on length_mm (OPEN.md item 6)"),
        ("density-1e-300", "/deployment/coil/material/density_g_cm3", 1e-300, "/deployment/coil/material/density_g_cm3",
         "density 1e-300 g/cm3 accepted: scene_parse.cpp needs a physical range (OPEN.md item 6)"),
        ("max-push-speed-1e308", "/deployment/max_push_speed_mm_s", 1e308, "/deployment/max_push_speed_mm_s", None),
        ("max-push-speed-1e9", "/deployment/max_push_speed_mm_s", 1e9, "/deployment/max_push_speed_mm_s",
         "max_push_speed_mm_s 1e9 switches the limit off: scene_parse.cpp needs a range (OPEN.md item 6)"),
        ("young-1e308-gpa", "/deployment/coil/material/young_modulus_gpa", 1e308,
         "/deployment/coil/material/young_modulus_gpa", None),
        ("young-1e200-gpa", "/deployment/coil/material/young_modulus_gpa", 1e200,
         "/deployment/coil/material/young_modulus_gpa", None),
        ("length-1e308-mm", "/deployment/coil/length_mm", 1e308, "/deployment/coil/length_mm", None),
        ("gravity-1e308", "/gravity_m_s2", [0, 1e308, 0], "/gravity_m_s2/1", None),
        ("gravity-1e9", "/gravity_m_s2", [0, 1e9, 0], "/gravity_m_s2",
         "gravity 1e9 m/s2 passes the reader and fails as a solver error: scene_parse.cpp needs a range (OPEN.md item 6)"),
        ("area-1e308", "/deployment/coil/section/area_mm2", 1e308, "/deployment/coil/section/area_mm2", None),
        ("area-1e9", "/deployment/coil/section/area_mm2", 1e9, "/deployment/coil/section/area_mm2",
         "section area 1e9 mm2 passes the reader: scene_parse.cpp needs a range (OPEN.md item 6)"),
        ("beams-100000", "/deployment/coil/beams", 100000, "/deployment/coil/beams",
         "beams 100000 is inside the documented range but fails at t = 0: scene_parse.cpp range (OPEN.md item 7)"),
        ("time-step-1", "/time_step_s", 1, "/time_step_s",
         "time_step_s 1 is inside the documented range but fails at t = 0: scene_parse.cpp range (OPEN.md item 7)"),
        ("time-step-0", "/time_step_s", 0, "/time_step_s", None),
        ("time-step-neg", "/time_step_s", -0.001, "/time_step_s", None),
        ("duration-1e9", "/duration_s", 1e9, "/duration_s", None),
        ("mesh-missing", "/obstacles/0/mesh", "no-such-mesh.stl", "no-such-mesh.stl", None),
        ("mesh-is-directory", "/obstacles/0/mesh", MESH_UP, "directory", None),
        ("mesh-is-json", "/obstacles/0/mesh", "../../../../scenes/default.json", "default.json", None),
        ("friction-neg", "/obstacles/0/friction", -1, "/obstacles/0/friction", None),
        ("direction-zero", "/deployment/catheter/direction", [0, 0, 0], "/deployment/catheter/direction", None),
        ("newton-0", "/newton_iterations", 0, "/newton_iterations", None),
        ("newton-1e308", "/newton_iterations", 1e308, "/newton_iterations", None),
        ("wire-radius-huge", "/deployment/coil/section/outer_radius_mm", 1e308,
         "/deployment/coil/section/outer_radius_mm", None),
    ]
    for name, p, v, sub, op in targeted:
        add("default." + name + ".json", "scene", dump(replaced(d, p, v)), SCENE_RUN, 2, ["{file}", sub],
            open_=op, timeout=20 if not op else 15)
    # Mesh in metres used at scale 1: an obstacle 0.014 mm across.
    mesh = ascii_stl(cube(0.0035), "metres")
    add("default.mesh-in-metres.json", "scene", dump(replaced(d, "/obstacles/0/mesh", "../mesh/cube-in-metres.stl")),
        SCENE_RUN, 2, ["cube-in-metres.stl", "metres"], extra={"mesh/cube-in-metres.stl": mesh})
    # A PLY obstacle with a face index out of range / negative.
    for tag in ("face-out-of-range", "face-negative"):
        add("default.obstacle-ply-%s.json" % tag, "scene",
            dump(replaced(d, "/obstacles/0/mesh", "../mesh/cube.ply-%s.ply" % tag)), SCENE_RUN, 2,
            ["cube.ply-%s.ply" % tag, "face"])
    # Structure: empty object, array root, nested depth, a BOM, binary junk, duplicate key.
    runs = [("empty-object", "{}", "/format"), ("array-root", "[]", "{file}"), ("null-root", "null", "{file}"),
            ("number-root", "1e999", "{file}"), ("string-root", '"scene"', "{file}"),
            ("deep-nesting", "[" * 5000 + "]" * 5000, "nested deeper"),
            ("deep-nesting-unclosed", "[" * 3000, "nested deeper"),
            ("deep-nesting-objects", '{"a":' * 300 + "1" + "}" * 300, "nested deeper"),
            ("bom", "\ufeff" + json.dumps(d), "{file}"),
            ("binary-junk", bytes(range(256)) * 2, "{file}"), ("nul-byte", '{"format"\x00:1}', "{file}"),
            ("duplicate-key", '{"format":"coilsim-scene/1","format":"coilsim-scene/1"}', "duplicate key"),
            ("bad-utf8", b'{"format":"coilsim-scene/1","name":"\xff\xfe"}', "{file}"),
            ("comment", '// scene\n' + json.dumps(d), "malformed JSON"),
            ("trailing-comma", '{"format":"coilsim-scene/1",}', "malformed JSON"),
            ("nan-literal", '{"format":"coilsim-scene/1","gravity_m_s2":[NaN,0,0]}', "malformed JSON"),
            ("wrong-format", json.dumps(replaced(d, "/format", "coilsim-scene/2")), "/format"),
            ("huge-integer", json.dumps(replaced(d, "/deployment/coil/beams", 2 ** 63)), "/deployment/coil/beams"),
            ("huge-negative-integer", json.dumps(replaced(d, "/deployment/coil/beams", -2 ** 63)),
             "/deployment/coil/beams"),
            ("long-string", json.dumps(replaced(d, "/name", "n" * 5000)), "{file}")]
    for name, text, sub in runs:
        ok = name in ("bom", "long-string")  # a BOM is tolerated by nlohmann; a long name is a name
        add("structure." + name + ".json", "scene", text, SCENE_RUN, 0 if ok else 2, ["{file}"] + ([sub] if sub != "{file}" else []))


# ---------------------------------------------------------------- meshes

def cube(h):
    v = [(x, y, z) for x in (-h, h) for y in (-h, h) for z in (-h, h)]
    # Outward triangles of the cube with vertex index 4x + 2y + z.
    t = [(0, 1, 3), (0, 3, 2), (4, 6, 7), (4, 7, 5), (0, 4, 5), (0, 5, 1),
         (2, 3, 7), (2, 7, 6), (0, 2, 6), (0, 6, 4), (1, 5, 7), (1, 7, 3)]
    return v, t


def fnum(x):
    return repr(float(x)) if isinstance(x, float) and x == x and abs(x) != float("inf") else str(x)


def ascii_stl(mesh, name="cube"):
    v, t = mesh
    out = ["solid %s" % name]
    for a, b, c in t:
        out.append(" facet normal 0 0 0\n  outer loop")
        for i in (a, b, c):
            out.append("   vertex %s %s %s" % tuple(fnum(x) for x in v[i]))
        out.append("  endloop\n endfacet")
    out.append("endsolid %s" % name)
    return "\n".join(out) + "\n"


def binary_stl(mesh, count=None, cut=None):
    v, t = mesh
    data = b"coilsim fuzz binary STL".ljust(80, b" ") + struct.pack("<I", len(t) if count is None else count)
    for a, b, c in t:
        data += struct.pack("<3f", 0, 0, 0)
        for i in (a, b, c):
            data += struct.pack("<3f", *v[i])
        data += struct.pack("<H", 0)
    return data if cut is None else data[:cut]


def ply_ascii(mesh, nv=None, nf=None, faces=None, verts=None, count_type="uchar", index_type="int"):
    v, t = mesh
    faces = [list(f) for f in t] if faces is None else faces
    verts = v if verts is None else verts
    head = ["ply", "format ascii 1.0", "element vertex %d" % (len(verts) if nv is None else nv),
            "property float x", "property float y", "property float z",
            "element face %d" % (len(faces) if nf is None else nf),
            "property list %s %s vertex_indices" % (count_type, index_type), "end_header"]
    body = ["%s %s %s" % tuple(fnum(x) for x in p) for p in verts]
    body += ["%d %s" % (len(f), " ".join(str(i) for i in f)) for f in faces]
    return "\n".join(head + body) + "\n"


def ply_binary(mesh, nv=None, nf=None, faces=None, cut=None, fmt="binary_little_endian"):
    v, t = mesh
    faces = [list(f) for f in t] if faces is None else faces
    e = "<" if fmt == "binary_little_endian" else ">"
    head = ("ply\nformat %s 1.0\nelement vertex %d\nproperty float x\nproperty float y\nproperty float z\n"
            "element face %d\nproperty list uchar int vertex_indices\nend_header\n" %
            (fmt, len(v) if nv is None else nv, len(faces) if nf is None else nf)).encode()
    body = b"".join(struct.pack(e + "3f", *p) for p in v)
    body += b"".join(struct.pack(e + "B", len(f)) + struct.pack(e + "%di" % len(f), *f) for f in faces)
    data = head + body
    return data if cut is None else data[:len(head) + cut]


def obj_text(mesh, faces=None, verts=None):
    v, t = mesh
    verts = v if verts is None else verts
    faces = [[i + 1 for i in f] for f in t] if faces is None else faces
    return "".join("v %s %s %s\n" % tuple(fnum(x) for x in p) for p in verts) + \
        "".join("f %s\n" % " ".join(str(i) for i in f) for f in faces)


def off_text(mesh, nv=None, nf=None, faces=None, verts=None):
    v, t = mesh
    verts = v if verts is None else verts
    faces = [list(f) for f in t] if faces is None else faces
    return "OFF\n%d %d 0\n" % (len(verts) if nv is None else nv, len(faces) if nf is None else nf) + \
        "".join("%s %s %s\n" % tuple(fnum(x) for x in p) for p in verts) + \
        "".join("%d %s\n" % (len(f), " ".join(str(i) for i in f)) for f in faces)


def meshes():
    c = cube(2.5)
    v, t = c
    M = ["mesh", "{file}"]
    ok = lambda name, data: add(name, "mesh", data, M, 0, ["{file}", "usable      yes"])
    bad = lambda name, data, sub, op=None, timeout=20: add(name, "mesh", data, M, 2, ["{file}"] + ([sub] if sub else []),
                                                           open_=op, timeout=timeout)
    ok("cube.stl", ascii_stl(c))
    ok("cube-binary.stl", binary_stl(c))
    ok("cube.ply", ply_ascii(c))
    ok("cube-binary.ply", ply_binary(c))
    ok("cube-big-endian.ply", ply_binary(c, fmt="binary_big_endian"))
    ok("cube.obj", obj_text(c))
    ok("cube.off", off_text(c))
    # PLY: indices against the vertex count, counts against what the file holds.
    bad("cube.ply-face-out-of-range.ply", ply_ascii(c, faces=[list(f) for f in t[:-1]] + [[1, 7, 99]]), "face")
    bad("cube.ply-face-negative.ply", ply_ascii(c, faces=[list(f) for f in t[:-1]] + [[1, 7, -3]]), "face")
    bad("cube.ply-face-huge-index.ply", ply_ascii(c, faces=[list(f) for f in t[:-1]] + [[1, 7, 2147483647]]), "face")
    bad("binary-face-out-of-range.ply", ply_binary(c, faces=[list(f) for f in t[:-1]] + [[1, 7, 99]]), "face")
    bad("binary-face-negative.ply", ply_binary(c, faces=[list(f) for f in t[:-1]] + [[1, 7, -1]]), "face")
    bad("header-1e8-vertices.ply", ply_ascii(c, nv=100000000, verts=v[:2], faces=[]), "vertex")
    bad("header-1e8-vertices-binary.ply", ply_binary((v[:2], []), nv=100000000), "vertex")
    bad("header-2e9-faces.ply", ply_ascii(c, nf=2000000000), "face")
    bad("header-negative-count.ply", ply_ascii(c, nv=-8), "vertex")
    bad("header-count-overflow.ply", ply_ascii(c, nv=2 ** 64 + 8).replace("vertex 18446744073709551624", "vertex 18446744073709551624"),
        "vertex")
    bad("list-count-255.ply", ply_ascii(c, faces=[list(f) for f in t[:-1]]).replace("\n3 1 7 3\n", "\n255 1 7 3\n") +
        "", "{file}")
    bad("face-count-short.ply", ply_ascii(c, nf=14), "face")
    bad("vertex-count-short.ply", ply_ascii(c, nv=9), "{file}")
    bad("binary-truncated.ply", ply_binary(c, cut=50), "{file}")
    bad("binary-list-count-250.ply", ply_binary(c, faces=[[0, 1, 3]] * 11 + [[0] * 250]), "{file}")
    # Found by scripts/fuzz (libFuzzer): faces of no vertex made assimp abort the process.
    bad("binary-faces-of-0-vertices.ply", ply_binary(c, faces=[[]] * 12), "face")
    bad("faces-of-0-vertices.ply", ply_ascii(c, faces=[[]] * 12), "face")
    bad("face-of-2-vertices.ply", ply_ascii(c, faces=[list(f) for f in t[:-1]] + [[1, 7]]), "face")
    # Found by scripts/fuzz: a header with binary bytes in a property name made assimp loop forever.
    bad("header-binary-bytes.ply", ply_ascii(c).encode().replace(b"vertex_indices", b"verte\xff\x00\xde\xff\xff\x7f"),
        "not text")
    bad("face-without-indices.ply", ply_ascii(c).replace("vertex_indices", "corners"), "vertex_indices")
    bad("no-end-header.ply", "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\n", "{file}")
    bad("unknown-format.ply", ply_ascii(c).replace("format ascii 1.0", "format ebcdic 1.0"), "format")
    bad("unknown-property-type.ply", ply_ascii(c).replace("property float x", "property quaternion x"), "{file}")
    bad("no-x-property.ply", ply_ascii(c).replace("property float x\n", ""), "{file}")
    bad("list-float-index.ply", ply_ascii(c, index_type="float"), "{file}")
    bad("nan-vertex.ply", ply_ascii(c, verts=[("nan", 0, 0)] + v[1:]), "finite")
    bad("inf-vertex.ply", ply_ascii(c, verts=[("inf", 0, 0)] + v[1:]), "finite")
    bad("1e308-vertex.ply", ply_ascii(c, verts=[(1e308, 0, 0)] + v[1:]), "{file}")
    bad("only-magic.ply", "ply\n", "{file}")
    bad("empty.ply", "", "{file}")
    bad("zero-faces.ply", ply_ascii(c, faces=[]), "triangle")
    # OFF.
    bad("face-out-of-range.off", off_text(c, faces=[list(f) for f in t[:-1]] + [[1, 7, 99]]), "face")
    bad("face-negative.off", off_text(c, faces=[list(f) for f in t[:-1]] + [[1, 7, -1]]), "face")
    bad("header-1e8-vertices.off", off_text(c, nv=100000000, verts=v[:2], faces=[]), "vert")
    bad("header-negative.off", off_text(c, nv=-1), "{file}")
    bad("face-count-short.off", off_text(c, nf=40), "face")
    bad("face-255-indices.off", off_text(c, faces=[list(f) for f in t[:-1]] + [[0] * 3 + [1] * 0]).replace("\n3 0 0 0\n", "\n255 0 0 0\n"),
        "{file}")
    bad("garbage-counts.off", "OFF\nx y z\n", "{file}")
    bad("empty.off", "", "{file}")
    # OBJ.
    bad("face-out-of-range.obj", obj_text(c, faces=[[i + 1 for i in f] for f in t[:-1]] + [[1, 2, 99]]), "face")
    bad("texture-out-of-range.obj", obj_text(c) + "vt 0 0\nf 1/1 2/2 3/1\n", "texture coordinate")
    bad("normal-out-of-range.obj", obj_text(c) + "vn 0 0 1\nf 1//1 2//1 3//7\n", "normal")
    bad("face-garbage-ref.obj", obj_text(c) + "f 1 2 x\n", "face")
    bad("face-zero.obj", obj_text(c, faces=[[i + 1 for i in f] for f in t[:-1]] + [[0, 1, 2]]), "face")
    bad("face-negative-beyond.obj", obj_text(c, faces=[[i + 1 for i in f] for f in t[:-1]] + [[-1, -2, -100]]), "face")
    ok("face-negative-relative.obj", obj_text(c, faces=[[i - 8 for i in f] for f in t]))
    bad("nan-vertex.obj", obj_text(c, verts=[("nan", 0, 0)] + v[1:]), "finite")
    bad("no-faces.obj", obj_text(c, faces=[]), "triangle")
    bad("faces-only.obj", "f 1 2 3\nf 2 3 4\n", "{file}")
    bad("empty.obj", "", "{file}")
    # STL.
    bad("binary-count-1e9.stl", binary_stl(c, count=1000000000), "{file}")
    bad("binary-count-short.stl", binary_stl(c, count=13), "{file}")
    bad("binary-truncated.stl", binary_stl(c, cut=84 + 50 * 5 + 17), "{file}")
    bad("binary-zero.stl", binary_stl(([], [])), "{file}")
    bad("binary-nan.stl", binary_stl(([(float("nan"), 0, 0)] + v[1:], t)), "finite")
    bad("binary-inf.stl", binary_stl(([(float("inf"), 0, 0)] + v[1:], t)), "finite")
    bad("ascii-truncated.stl", ascii_stl(c)[:700], "{file}")
    bad("ascii-nan.stl", ascii_stl(([("nan", 0, 0)] + v[1:], t)), "finite")
    bad("ascii-no-facets.stl", "solid x\nendsolid x\n", "{file}")
    bad("json-as-stl.stl", '{"format": "coilsim-scene/1"}\n', "{file}")
    bad("header-only.stl", b"\0" * 80, "{file}")
    bad("empty.stl", "", "{file}")
    bad("open-surface.stl", ascii_stl((v, t[:-2])), "open")
    bad("degenerate.stl", ascii_stl(([(0, 0, 0)] * 8, t)), "{file}")
    bad("cube-in-metres.stl", ascii_stl(cube(0.0035)), "metres")
    bad("cube-1km.stl", ascii_stl(cube(5e5)), "{file}")
    bad("unknown-extension.xyz", "1 2 3\n4 5 6\n", "{file}")
    ok("no-extension", ascii_stl(c))  # assimp knows STL by its content
    # Not a file at all.
    add("directory", "mesh", None, ["mesh", "{corpus}/mesh"], 2, ["{corpus}/mesh", "directory"])
    add("missing", "mesh", None, ["mesh", "{corpus}/mesh/no-such-file.stl"], 2, ["no-such-file.stl"])
    # Scale: finite and > 0.
    add("scale-nan", "mesh", None, ["mesh", "{corpus}/mesh/cube.stl", "--scale-to-mm", "nan"], 2, ["--scale-to-mm"])
    add("scale-1e308", "mesh", None, ["mesh", "{corpus}/mesh/cube.stl", "--scale-to-mm", "1e308"], 2, ["cube.stl"])
    add("scale-1e-300", "mesh", None, ["mesh", "{corpus}/mesh/cube.stl", "--scale-to-mm", "1e-300"], 2, ["cube.stl"])
    ok("cube-in-metres-scaled.stl", ascii_stl(cube(0.0025)))
    entries[-1]["args"] = ["mesh", "{file}", "--scale-to-mm", "1000"]


# ---------------------------------------------------------------- timelines

def timelines():
    TL = ["run", "{src}/scenes/free-deploy-helix.json", "--headless", "--steps", "2", "--input", "{file}",
          "--out", "{out}/result.json"]
    for f in sorted(os.listdir(rel("timelines"))):
        doc = load("timelines/" + f)
        base = f[:-5]
        add(base + ".valid.json", "timeline", json.dumps(doc, indent=1) + "\n", TL, 0, [], timeout=30)
        json_mutations("timeline", base, doc, TL, 4, 3, text=json.dumps(doc, indent=1), skip=("/description", "/name"))
    cmd = lambda *c: {"format": "coilsim-timeline/1", "commands": list(c)}
    T = [
        ("retract-1e308", cmd({"t_s": 0, "retract": {"speed_mm_s": 1, "distance_mm": 1e308}}), "/commands/0/retract/distance_mm"),
        ("retract-1e6", cmd({"t_s": 0, "retract": {"speed_mm_s": 1, "distance_mm": 1e6}}), "/commands/0/retract/distance_mm"),
        ("push-speed-1e308", cmd({"t_s": 0, "push": {"speed_mm_s": 1e308}}), "/commands/0/push/speed_mm_s"),
        ("push-speed-1e-300", cmd({"t_s": 0, "push": {"speed_mm_s": 1e-300}}), "/commands/0/push/speed_mm_s"),
        ("twist-rate-1e308", cmd({"t_s": 0, "twist": {"rate_deg_s": 1e308}}), "/commands/0/twist/rate_deg_s"),
        ("twist-rate-zero", cmd({"t_s": 0, "twist": {"rate_deg_s": 0}}), "/commands/0/twist/rate_deg_s"),
        ("twist-angle-1e308", cmd({"t_s": 0, "twist": {"rate_deg_s": 10, "angle_deg": 1e308}}), "/commands/0/twist/angle_deg"),
        ("time-1e308", cmd({"t_s": 1e308, "stop": {}}), "/commands/0/t_s"),
        ("time-1e9", cmd({"t_s": 1e9, "stop": {}}), "/commands/0/t_s"),
        ("time-negative", cmd({"t_s": -1, "stop": {}}), "/commands/0/t_s"),
        ("time-backwards", cmd({"t_s": 2, "stop": {}}, {"t_s": 1, "stop": {}}), "/commands/1/t_s"),
        ("two-kinds", cmd({"t_s": 0, "stop": {}, "detach": {}}), "/commands/0"),
        ("no-kind", cmd({"t_s": 0}), "/commands/0"),
        ("stop-with-args", cmd({"t_s": 0, "stop": {"now": True}}), "/commands/0/stop/now"),
        ("push-negative-speed", cmd({"t_s": 0, "push": {"speed_mm_s": -5}}), "/commands/0/push/speed_mm_s"),
        ("push-zero-distance", cmd({"t_s": 0, "push": {"speed_mm_s": 5, "distance_mm": 0}}), "/commands/0/push/distance_mm"),
        ("command-not-object", cmd(5), "/commands/0"),
        ("commands-not-array", {"format": "coilsim-timeline/1", "commands": {}}, "/commands"),
        ("no-commands", {"format": "coilsim-timeline/1"}, "/commands"),
        ("wrong-format", {"format": "coilsim-scene/1", "commands": []}, "/format"),
    ]
    for name, doc, sub in T:
        add(name + ".json", "timeline", dump(doc), TL, 2, ["{file}", sub])
    many = cmd(*[{"t_s": 0, "stop": {}}] * 2000)
    add("2000-stops.json", "timeline", dump(many), TL, 0, [], timeout=30)
    add("empty-commands.json", "timeline", dump(cmd()), TL, 0, [])
    add("directory", "timeline", None, TL[:6] + ["{corpus}/timeline", "--out", "{out}/r.json"], 2,
        ["{corpus}/timeline", "directory"])


# ---------------------------------------------------------------- measurements

VALIDATE = ["validate", "{file}", "--out", "{out}", "--no-plots", "--quiet"]
DIAGNOSE = ["diagnose", "{file}", "--out", "{out}"]


def measurements():
    doc = load("examples/measurements/soft-catheter-helix.json")
    # Shorter centre lines keep inputs tiny; the first stage only (others refer to the same coil).
    small = copy.deepcopy(doc)
    for s in small["stages"]:
        pts = s["centerline_mm"]
        keep = list(range(0, len(pts), 6))
        if keep[-1] != len(pts) - 1:
            keep.append(len(pts) - 1)
        s["centerline_mm"] = [list(pts[i]) for i in keep]  # copies: no shared lists for the mutations
    small["stages"] = small["stages"][:1]
    json_mutations("measurement", "soft-catheter-helix", small, VALIDATE, 14, 8, text=json.dumps(small, indent=1),
                   skip=("/description", "/name", "/stages/0/name"), unknown_keys_ignored=True)
    st = "/stages/0"
    pts = small["stages"][0]["centerline_mm"]
    T = [
        ("identical-points-all", st + "/centerline_mm", [pts[0]] * len(pts), st + "/centerline_mm", VALIDATE),
        ("identical-points-all-diagnose", st + "/centerline_mm", [pts[0]] * len(pts), st + "/centerline_mm", DIAGNOSE),
        ("identical-points-two", st + "/centerline_mm", [pts[0], pts[0]], st + "/centerline_mm", VALIDATE),
        ("identical-points-two-diagnose", st + "/centerline_mm", [pts[0], pts[0]], st + "/centerline_mm", DIAGNOSE),
        ("identical-points-some", st + "/centerline_mm", pts[:3] + [pts[2]] + pts[3:], st + "/centerline_mm", VALIDATE),
        ("one-point", st + "/centerline_mm", pts[:1], st + "/centerline_mm", VALIDATE),
        ("centreline-1e6-from-tip", st + "/centerline_mm", [[1e6 + p[0], p[1], p[2]] for p in pts],
         st + "/centerline_mm", VALIDATE),
        ("twist-1e308", st + "/twist_deg", 1e308, st + "/twist_deg", VALIDATE),
        ("twist-1e9", st + "/twist_deg", 1e9, st + "/twist_deg", VALIDATE),
        ("loop-1e-9-mm", "/coil/rest_shape/loop_diameter_mm", 1e-9, "/coil/rest_shape/loop_diameter_mm", VALIDATE),
        ("pitch-1e9", "/coil/rest_shape/pitch_mm", 1e9, "/coil/rest_shape/pitch_mm", VALIDATE),
        ("length-1e308", "/coil/length_mm", 1e308, "/coil/length_mm", VALIDATE),
        ("mass-1e308", "/coil/mass_g", 1e308, "/coil/mass_g", VALIDATE),
        ("young-1e308", "/coil/young_modulus_gpa", 1e308, "/coil/young_modulus_gpa", VALIDATE),
        ("wire-radius-1e308", "/coil/wire_radius_mm", 1e308, "/coil/wire_radius_mm", VALIDATE),
        ("gravity-1e308", "/setup/gravity_m_s2", [0, 0, -1e308], "/setup/gravity_m_s2/2", VALIDATE),
        ("deployed-beyond-coil", st + "/deployed_length_mm", 81, st + "/deployed_length_mm", VALIDATE),
        ("direction-not-unit", "/setup/catheter_tip/direction", [2, 0, 0], "/setup/catheter_tip/direction", VALIDATE),
        ("normal-not-orthogonal", "/setup/catheter_tip/reference_normal", [1, 0, 0],
         "/setup/catheter_tip/reference_normal", VALIDATE),
        ("stages-empty", "/stages", [], "/stages", VALIDATE),
        ("sigma-negative", st + "/point_sigma_mm", -1, st + "/point_sigma_mm", VALIDATE),
    ]
    for name, p, v, sub, args in T:
        add(name + ".json", "measurement", dump(replaced(small, p, v)), args, 2, ["{file}", sub])
    # Push histories (dynamic stages).
    dyn = copy.deepcopy(small)
    dyn["stages"][0]["push_history"] = [[0, 0, 0], [5, 25, 0]]
    dyn["stages"][0]["capture_time_s"] = 6
    H = [
        ("capture-time-1e308", st + "/capture_time_s", 1e308, st + "/capture_time_s"),
        ("capture-time-1e7", st + "/capture_time_s", 1e7, st + "/capture_time_s"),
        ("capture-before-history", st + "/capture_time_s", -1, st + "/capture_time_s"),
        ("history-time-1e308", st + "/push_history", [[0, 0, 0], [1e308, 25, 0]], st + "/push_history/1/0"),
        ("history-out-of-order", st + "/push_history", [[1, 0, 0], [0, 25, 0]], st + "/push_history/1/0"),
        ("history-equal-times", st + "/push_history", [[0, 0, 0], [0, 25, 0]], st + "/push_history/1/0"),
        ("history-beyond-coil", st + "/push_history", [[0, 0, 0], [5, 90, 0]], st + "/push_history/1/1"),
        ("history-twist-1e308", st + "/push_history", [[0, 0, 0], [5, 25, 1e308]], st + "/push_history/1/2"),
        ("history-row-short", st + "/push_history", [[0, 0]], st + "/push_history/0"),
        ("history-empty", st + "/push_history", [], st + "/push_history"),
    ]
    for name, p, v, sub in H:
        add(name + ".json", "measurement", dump(replaced(dyn, p, v)), VALIDATE, 2, ["{file}", sub])
    nocap = copy.deepcopy(dyn)
    del nocap["stages"][0]["capture_time_s"]
    add("history-without-capture.json", "measurement", dump(nocap), VALIDATE, 2, ["{file}", st + "/capture_time_s"])
    add("directory", "measurement", None, ["validate", "{corpus}/measurement", "--out", "{out}"], 2,
        ["{corpus}/measurement", "directory"])
    add("directory-diagnose", "measurement", None, ["diagnose", "{corpus}/measurement", "--out", "{out}"], 2,
        ["{corpus}/measurement", "directory"])


# ---------------------------------------------------------------- coil catalogue entries

def coils():
    # Each entry is a catalogue directory holding one coil file; plan reads the
    # catalogue before anything else, so a bad coil fails at once.
    args = ["plan", "{src}/scenes/cases/sphere-7mm-wide-neck.json", "--catalogue", "{dir}", "--coils", "x",
            "--out", "{out}", "--no-screenshots"]
    files = sorted(os.listdir(rel("assets/coils")))
    for i, f in enumerate(files):
        doc = load("assets/coils/" + f)
        base = f[:-5]
        n_type, n_num = (3, 2) if i % 2 == 0 else (2, 2)
        json_mutations("coil", base, doc, args, n_type, n_num, text=json.dumps(doc, indent=1) if i < 2 else None,
                       skip=("/description", "/name", "/sources"),
                       file_path=lambda tag: os.path.join("coil", tag[:-5], "coil.json"))
    doc = load("assets/coils/finishing-2x10.json")
    T = [
        ("loop-1e-9", "/loop_diameter_mm", 1e-9, "/loop_diameter_mm"),
        ("length-1e6", "/length_mm", 1e6, "/length_mm"),
        ("wire-thicker-than-primary", "/wire/diameter_mm", 0.2, "/wire/diameter_mm"),
        ("young-1e308", "/wire/young_modulus_gpa", 1e308, "/wire/young_modulus_gpa"),
        ("density-1e-300", "/wire/density_g_cm3", 1e-300, "/wire/density_g_cm3"),
        ("bending-wrong", "/bending_stiffness_n_mm2", 1.0, "/bending_stiffness_n_mm2"),
        ("sources-too-many", "/sources", ["s"] * 51, "/sources"),
        ("family-unknown", "/family", "embolic", "/family"),
    ]
    for name, p, v, sub in T:
        add(name, "coil", dump(replaced(doc, p, v)), args, 2, ["{file}", sub],
            path=os.path.join("coil", "finishing-2x10." + name, "coil.json"))
    # The same name twice in one catalogue.
    add("duplicate-name", "coil", dump(doc), args, 2, ["{dir}", "/name"],
        path=os.path.join("coil", "duplicate-name", "a.json"),
        extra={os.path.join("coil", "duplicate-name", "b.json"): dump(doc)})
    entries[-1]["contains"] = ["duplicate-name", "/name"]
    add("empty-directory", "coil", "not a coil\n", args, 2, ["{dir}"],
        path=os.path.join("coil", "empty-directory", "README.txt"))
    add("missing-directory", "coil", None, args[:3] + ["{corpus}/coil/no-such-dir"] + args[4:], 2, ["no-such-dir"])


# ---------------------------------------------------------------- case files

def cases():
    args = ["practice", "{file}", "--input", "{src}/timelines/push-default.json", "--duration", "0.01",
            "--out", "{out}/score.json"]
    for f in sorted(os.listdir(rel("scenes/cases"))):
        doc = load("scenes/cases/" + f)
        base = f[:-5]
        add(base + ".valid.json", "case", json.dumps(doc, indent=1) + "\n", args, 0, [], timeout=60)
        json_mutations("case", base, doc, args, 10, 5, text=json.dumps(doc, indent=1), path_strip="/scene",
                       skip=("/description", "/name", "/scene/description", "/scene/name"))
    doc = load("scenes/cases/sphere-7mm-wide-neck.json")
    neck = doc["sac"]["neck_plane"]
    T = [
        ("sac-radius-in-metres", "/sac/sphere/radius_mm", 0.0035, "/sac/sphere/radius_mm"),
        ("sac-mesh-in-metres", "/sac", {"mesh": "../mesh/cube-in-metres.stl", "neck_plane": neck}, "cube-in-metres.stl"),
        ("sac-mesh-face-out-of-range", "/sac", {"mesh": "../mesh/cube.ply-face-out-of-range.ply", "neck_plane": neck},
         "cube.ply-face-out-of-range.ply"),
        ("sac-mesh-missing", "/sac", {"mesh": "no-such.stl", "neck_plane": neck}, "no-such.stl"),
        ("sac-mesh-directory", "/sac", {"mesh": "../mesh", "neck_plane": neck}, "directory"),
        ("sac-two-kinds", "/sac", {"mesh": "x.stl", "sphere": doc["sac"]["sphere"], "neck_plane": neck}, "/sac"),
        ("sac-neck-misses", "/sac/neck_plane/point_mm", [0, 0, 100], "/sac/neck_plane"),
        ("sac-normal-zero", "/sac/neck_plane/normal", [0, 0, 0], "/sac/neck_plane/normal"),
        ("sac-subdivisions-1e9", "/sac/sphere/subdivisions", 1000000000, "/sac/sphere/subdivisions"),
        ("sac-phantom-no-sidecar", "/sac", {"phantom": "../mesh/cube.stl"}, "phantom.json"),
        ("scene-path-missing", "/scene", "no-such-scene.json", "no-such-scene.json"),
        ("scene-path-directory", "/scene", "../scene", "directory"),
        ("scene-without-deployment", "/scene", "../../../../scenes/cantilever-static.json", "deployment"),
        ("coils-empty", "/coils", [], "/coils"),
        ("coils-unknown", "/coils", ["no-such-coil"], "/coils/0"),
        ("coils-51", "/coils", ["finishing-2x10"] * 51, "/coils"),
        ("catalogue-missing", "/catalogue", "no-such-dir", "no-such-dir"),
        ("catalogue-is-file", "/catalogue", "sphere-7mm-wide-neck.valid.json", "sphere-7mm-wide-neck.valid.json"),
        ("goal-density-2", "/goal/min_packing_density", 2, "/goal/min_packing_density"),
        ("goal-force-1e308", "/goal/max_wall_force_mN", 1e308, "/goal/max_wall_force_mN"),
        ("spacing-1e-300", "/spacing_mm", 1e-300, "/spacing_mm"),
        ("coil-1km", "/scene/deployment/coil/length_mm", 1e6, "/deployment/coil/length_mm"),
    ]
    for name, p, v, sub in T:
        op = None
        if name == "coil-1km":
            op = "a 1 km coil in a case scene runs without a word: scene_parse.cpp range on length_mm (OPEN.md item 6)"
        add(name + ".json", "case", dump(replaced(doc, p, v)), args, 2, ["{file}", sub] if "/" in sub else [sub],
            open_=op, timeout=15 if op else 20)


# ---------------------------------------------------------------- practice sessions

CASE7 = "{src}/scenes/cases/sphere-7mm-wide-neck.json"


def sessions():
    args = ["practice", CASE7, "--replay", "{file}", "--out", "{out}/score.json"]
    base = {"format": "coilsim-session/1", "case": "scenes/cases/sphere-7mm-wide-neck.json", "coil": "finishing-2x10",
            "end_s": 0.02,
            "timeline": {"format": "coilsim-timeline/1",
                         "commands": [{"t_s": 0, "push": {"speed_mm_s": 10, "distance_mm": 1}}]},
            "views": [{"t_s": 0, "view": "xray"}]}
    add("valid.json", "session", json.dumps(base, indent=1) + "\n", args, 0, [])
    # A session's timeline is read as a timeline: its paths are the timeline's, the file labelled "(/timeline)".
    json_mutations("session", "base", base, args, 10, 4, text=json.dumps(base, indent=1), path_strip="/timeline")
    T = [
        ("end-3601", "/end_s", 3601, "/end_s", None),
        ("end-1e308", "/end_s", 1e308, "/end_s", None),
        ("end-negative", "/end_s", -1, "/end_s", None),
        ("coil-not-in-case", "/coil", "helical-10x200", "/coil",
         "a session naming a coil the case lacks is blamed on the case file (/coils), not on the session's /coil: "
         "practice.cpp (OPEN.md item 5)"),
        ("views-backwards", "/views", [{"t_s": 1, "view": "3d"}, {"t_s": 0, "view": "xray"}], "/views/1/t_s", None),
        ("view-unknown", "/views", [{"t_s": 0, "view": "side"}], "/views/0/view", None),
        ("timeline-bad-speed", "/timeline/commands/0/push/speed_mm_s", "fast", "/timeline", None),
        ("timeline-not-object", "/timeline", [], "/timeline", None),
    ]
    for name, p, v, sub, op in T:
        add(name + ".json", "session", dump(replaced(base, p, v)), args, 2, ["{file}", sub], open_=op)
    # Refused device commands must be reported (stderr, score sheet, recording), not dropped.
    refused = replaced(base, "/timeline/commands", [{"t_s": 0, "detach": {}}])
    add("refused-detach-before-push.json", "session", dump(refused), args, 0, ["refused"],
        open_="a refused device command in a practice session is dropped silently: practice.cpp / session_scorer.cpp "
              "(OPEN.md item 4)")
    twist = replaced(base, "/timeline/commands", [{"t_s": 0, "twist": {"rate_deg_s": 1e308}}])
    add("twist-rate-1e308.json", "session", dump(twist), args, 2, ["{file}", "/commands/0/twist/rate_deg_s"])
    other = replaced(base, "/case", "scenes/cases/sphere-10mm-narrow-neck.json")
    add("names-another-case.json", "session", dump(other), args, 2, ["{file}", "/case"],
        open_="a session recorded on another case is replayed against this one without a word: practice_cmd.cpp "
              "(OPEN.md item 5)")
    add("directory", "session", None, args[:3] + ["{corpus}/session"] + args[4:], 2, ["{corpus}/session", "directory"])


# ---------------------------------------------------------------- command lines

def command_lines():
    S = "{src}/scenes/cantilever-static.json"
    D = "{src}/scenes/free-deploy-helix.json"
    TL = "{src}/timelines/push-helix.json"
    M = "{src}/examples/measurements/soft-catheter-helix.json"
    C = [
        # name, args, exit, contains, open
        ("no-arguments", [], 2, ["usage"], None),
        ("help", ["help"], 0, ["usage"], None),
        ("help-extra", ["help", "x"], 2, ["help"], None),
        ("version", ["--version"], 0, ["coilsim"], None),
        ("unknown-command", ["--frobnicate"], 2, ["--frobnicate"], None),
        ("run-no-scene", ["run"], 2, ["needs SCENE"], None),
        ("run-missing-scene", ["run", "{out}/no-such.json", "--headless"], 2, ["no-such.json"], None),
        ("run-directory", ["run", "{src}/scenes", "--headless"], 2, ["scenes", "directory"], None),
        ("run-two-scenes", ["run", S, S, "--headless"], 2, ["one SCENE"], None),
        ("run-duration-nan", ["run", D, "--headless", "--duration", "nan"], 2, ["--duration needs"], None),
        ("run-duration-inf", ["run", D, "--headless", "--duration", "inf"], 2, ["--duration needs"], None),
        ("run-duration-zero", ["run", D, "--headless", "--duration", "0"], 2, ["--duration needs"], None),
        ("run-duration-empty", ["run", D, "--headless", "--duration", ""], 2, ["--duration needs"], None),
        ("run-duration-missing", ["run", D, "--headless", "--duration"], 2, ["--duration needs"], None),
        ("run-duration-1e9", ["run", D, "--headless", "--duration", "1e9"], 2, ["--duration"], None),
        ("run-duration-1e308", ["run", D, "--headless", "--duration", "1e308"], 2, ["--duration"], None),
        ("run-steps-1e9", ["run", D, "--headless", "--steps", "1000000000"], 2, ["--steps"], None),
        ("run-steps-1e9-plus-1", ["run", D, "--headless", "--steps", "1000000001"], 2, ["--steps needs"], None),
        ("run-steps-negative", ["run", D, "--headless", "--steps", "-1"], 2, ["--steps needs"], None),
        ("run-steps-float", ["run", D, "--headless", "--steps", "1.5"], 2, ["--steps needs"], None),
        ("run-steps-overflow", ["run", D, "--headless", "--steps", "99999999999999999999999"], 2, ["--steps needs"], None),
        ("run-duration-and-steps", ["run", D, "--headless", "--steps", "2", "--duration", "1"], 2, ["not both"], None),
        ("run-out-then-option", ["run", D, "--headless", "--out", "--steps", "2"], 2, ["--out needs"], None),
        ("run-input-then-option", ["run", D, "--headless", "--input", "--steps", "2"], 2, ["--input needs"], None),
        ("run-out-directory", ["run", S, "--headless", "--out", "{src}/scenes"], 2, ["scenes"], None),
        ("run-out-missing-dir", ["run", S, "--headless", "--out", "{out}/no/such/dir/r.json"], 2, ["r.json"], None),
        ("run-input-directory", ["run", D, "--headless", "--steps", "2", "--input", "{src}/timelines"], 2,
         ["timelines", "directory"], None),
        ("run-input-static", ["run", S, "--headless", "--input", TL], 2, ["deployment"], None),
        ("run-view-unknown", ["run", S, "--headless", "--view", "side"], 2, ["--view needs"], None),
        ("run-size-huge", ["run", S, "--headless", "--size", "100000x100000"], 2, ["--size needs"], None),
        ("run-size-garbage", ["run", S, "--headless", "--size", "x"], 2, ["--size"], None),
        ("run-headless-value", ["run", S, "--headless=yes"], 2, ["--headless"], None),
        ("run-unknown-option", ["run", S, "--fast"], 2, ["--fast"], None),
        ("run-static-ok", ["run", S, "--headless", "--out", "{out}/r.json"], 0, ["cantilever-static.json"], None),
        ("run-dynamic-2-steps", ["run", D, "--headless", "--steps", "2"], 0, [], None),
        ("mesh-none", ["mesh"], 2, ["needs FILE"], None),
        ("mesh-two", ["mesh", "a.stl", "b.stl"], 2, ["one FILE"], None),
        ("mesh-scale-missing", ["mesh", "a.stl", "--scale-to-mm"], 2, ["--scale-to-mm needs"], None),
        ("phantom-no-type", ["phantom", "--sac-mm", "7", "--out", "{out}/p.stl"], 2, ["--type is required"], None),
        ("phantom-sac-1e308", ["phantom", "--type", "sidewall", "--sac-mm", "1e308", "--out", "{out}/p.stl"], 2,
         ["--sac-mm needs"], None),
        ("phantom-sac-nan", ["phantom", "--type", "sidewall", "--sac-mm", "nan", "--out", "{out}/p.stl"], 2,
         ["--sac-mm needs"], None),
        ("phantom-resolution-1e-300", ["phantom", "--type", "sidewall", "--sac-mm", "7", "--resolution-mm", "1e-300",
                                       "--out", "{out}/p.stl"], 2, ["--resolution-mm needs"], None),
        ("phantom-out-not-stl", ["phantom", "--type", "sidewall", "--sac-mm", "7", "--out", "{out}/p.obj"], 2,
         [".stl"], None),
        ("phantom-lobes-1e9", ["phantom", "--type", "sidewall", "--sac-mm", "7", "--lobes", "1000000000",
                               "--out", "{out}/p.stl"], 2, ["--lobes needs"], None),
        ("plan-no-out", ["plan", CASE7], 2, ["needs --out"], None),
        ("plan-sensitivity-1e308", ["plan", CASE7, "--coils", "finishing-2x10", "--sensitivity", "1e308,1e308",
                                    "--out", "{out}", "--no-screenshots"], 2, ["--sensitivity needs"],
         "plan --sensitivity 1e308,1e308 is accepted and drives positions non-finite (UB in detect_rods.cpp:63): "
         "plan_cmd.cpp must bound it (OPEN.md item 1)"),
        ("plan-spacing-1e-300", ["plan", CASE7, "--coils", "finishing-2x10", "--spacing", "1e-300", "--out", "{out}",
                                 "--no-screenshots"], 2, ["--spacing needs"],
         "plan --spacing 1e-300 is accepted: plan_cmd.cpp must bound it (OPEN.md item 1)"),
        ("plan-speed-1e308", ["plan", CASE7, "--coils", "finishing-2x10", "--speed", "1e308", "--out", "{out}",
                              "--no-screenshots"], 2, ["--speed needs"],
         "plan --speed 1e308 is accepted: plan_cmd.cpp must bound it (OPEN.md item 1)"),
        ("plan-max-time-1e308", ["plan", CASE7, "--coils", "finishing-2x10", "--max-time", "1e308", "--out", "{out}",
                                 "--no-screenshots"], 2, ["--max-time needs"],
         "plan --max-time 1e308 is accepted: plan_cmd.cpp must bound it (OPEN.md item 1)"),
        ("plan-jobs-0", ["plan", CASE7, "--jobs", "0", "--out", "{out}"], 2, ["--jobs needs"], None),
        ("plan-unknown-coil", ["plan", CASE7, "--coils", "nope", "--out", "{out}", "--no-screenshots"], 2, ["nope"],
         None),
        ("plan-scene-without-sac", ["plan", D, "--coils", "finishing-2x10", "--out", "{out}"], 2, ["--sac"], None),
        ("plan-catalogue-directory-missing", ["plan", CASE7, "--catalogue", "{out}/none", "--out", "{out}"], 2,
         ["none"], None),
        ("plan-input-directory", ["plan", "{src}/scenes", "--out", "{out}"], 2, ["scenes", "directory"], None),
        ("plan-merge-nothing", ["plan-merge", "--out", "{out}"], 2, ["plan-merge"], None),
        ("plan-merge-missing", ["plan-merge", "{out}/none", "--out", "{out}/m"], 2, ["none"], None),
        ("practice-no-out", ["practice", CASE7, "--input", TL], 2, ["needs --out"], None),
        ("practice-duration-nan", ["practice", CASE7, "--input", TL, "--duration", "nan", "--out", "{out}/s.json"], 2,
         ["--duration needs"], None),
        ("practice-duration-1e9", ["practice", CASE7, "--input", "{src}/timelines/push-default.json", "--duration", "1e9",
                                   "--out", "{out}/s.json"], 2, ["--duration needs"],
         "practice --duration 1e9 runs for hours: practice_cmd.cpp must refuse durations over 3600 s (OPEN.md item 3)"),
        ("practice-duration-4000-record", ["practice", CASE7, "--input", "{src}/timelines/push-default.json",
                                           "--duration", "4000", "--record", "{out}/rec.json", "--out", "{out}/s.json"],
         2, ["--duration needs"],
         "practice --duration 4000 --record writes a session its own --replay refuses (end over 3600 s): "
         "practice_cmd.cpp (OPEN.md item 3)"),
        ("practice-out-then-option", ["practice", CASE7, "--input", TL, "--out", "--duration", "1"], 2, ["--out needs"],
         "practice --out followed by another option takes it as the file name: practice_cmd.cpp (OPEN.md item 8)"),
        ("practice-replay-and-input", ["practice", CASE7, "--input", TL, "--replay", TL, "--out", "{out}/s.json"], 2,
         ["give either"], None),
        ("practice-views-garbage", ["practice", CASE7, "--input", TL, "--views", "x:y", "--out", "{out}/s.json"], 2,
         ["--views needs"], None),
        ("practice-views-1e308", ["practice", CASE7, "--input", TL, "--views", "1e999:xray", "--out", "{out}/s.json"],
         2, ["--views needs"], None),
        ("practice-coil-unknown", ["practice", CASE7, "--input", "{src}/timelines/push-default.json", "--coil", "nope",
                                   "--duration", "0.01", "--out", "{out}/s.json"], 2, ["nope"], None),
        ("practice-case-directory", ["practice", "{src}/scenes/cases", "--input", TL, "--out", "{out}/s.json"], 2,
         ["cases", "directory"], None),
        ("practice-out-directory", ["practice", CASE7, "--input", TL, "--out", "{src}/scenes"], 2, ["scenes"], None),
        ("validate-no-out", ["validate", M], 2, ["--out DIR is needed"], None),
        ("validate-effects-unknown", ["validate", M, "--effects", "magic", "--out", "{out}"], 2, ["magic"], None),
        ("validate-fit-unknown", ["validate", M, "--fit", "magic", "--out", "{out}"], 2, ["magic"], None),
        ("validate-spacing-1e-300", ["validate", M, "--spacing", "1e-300", "--out", "{out}"], 2, ["--spacing needs"], None),
        ("validate-spacing-1e308", ["validate", M, "--spacing", "1e308", "--out", "{out}"], 2, ["--spacing needs"], None),
        ("validate-push-increment-nan", ["validate", M, "--push-increment", "nan", "--out", "{out}"], 2,
         ["--push-increment needs"], None),
        ("validate-out-then-option", ["validate", M, "--out", "--quiet"], 2, ["--out needs"], None),
        ("diagnose-candidates-empty", ["diagnose", M, "--candidates", ",", "--out", "{out}"], 2, ["--candidates needs"], None),
        ("diagnose-candidates-unknown", ["diagnose", M, "--candidates", "magic", "--out", "{out}"], 2, ["magic"], None),
        ("bench-unknown", ["bench", "--slow"], 2, ["--slow"], None),
    ]
    for name, args, code, contains, op in C:
        timeout = 10 if op and "hours" in op else 20
        add(name, "cli", None, args, code, contains, open_=op, timeout=timeout)


def tree(root):
    """{relative path: bytes} of every file below root."""
    out = {}
    for d, _, files in os.walk(root):
        for f in files:
            p = os.path.join(d, f)
            with open(p, "rb") as fh:
                out[os.path.relpath(p, root)] = fh.read()
    return out


def main():
    global OUT
    if sys.argv[1:] == ["--check"]:
        # Regenerates into a scratch directory: the committed corpus must be identical.
        import tempfile
        with tempfile.TemporaryDirectory() as scratch:
            OUT = os.path.join(scratch, "corpus")
            generate()
            want, have = tree(OUT), tree(CORPUS)
        diff = sorted(p for p in set(want) | set(have) if want.get(p) != have.get(p))
        if diff:
            print("generate.py --check: the corpus differs from what generate.py writes (rerun it and commit):")
            for p in diff[:20]:
                print("  " + p + ("" if p in have else " (missing)") + ("" if p in want else " (not generated)"))
            return 1
        print("generate.py --check: the corpus is what generate.py writes (%d files)" % len(want))
        return 0
    if sys.argv[1:]:
        print("usage: generate.py [--check]", file=sys.stderr)
        return 2
    generate()
    return 0


def generate():
    if os.path.isdir(OUT):
        shutil.rmtree(OUT)
    os.makedirs(OUT)
    meshes()
    scenes()
    timelines()
    measurements()
    coils()
    cases()
    sessions()
    command_lines()
    with open(os.path.join(OUT, "manifest.json"), "w") as f:
        # One entry a line: small, and a diff shows which entries changed.
        f.write('{"format": "coilsim-fuzz-corpus/1",\n "description": "written by tests/fuzz/generate.py; '
                'run by tests/fuzz/run_corpus.py",\n "entries": [\n')
        f.write(",\n".join("  " + json.dumps(e, separators=(",", ":")) for e in entries))
        f.write("\n ]\n}\n")
    kinds = {}
    for e in entries:
        kinds[e["kind"]] = kinds.get(e["kind"], 0) + 1
    print("%d entries (%s), %d open" % (len(entries), ", ".join("%s %d" % kv for kv in sorted(kinds.items())),
                                        sum(1 for e in entries if "open" in e)))


if __name__ == "__main__":
    sys.exit(main())
