#!/bin/sh
# docs/scene.schema.json against the scenes grape reads: every scenes/*.json and every JSON
# example in docs/scene-format.md must validate, and a scene with a misspelt field, a child
# of two kinds or a bad position type must not; every 3-D path example (after <!-- path3 -->)
# must validate as $defs/path3, and a 3-D path with a 2-D point or a misspelt field must not.
# Exits 0 (as expected), 1 (not) or 77 (skipped: python3 with jsonschema, Debian's
# python3-jsonschema, is missing).
#   tests/tool_scene_schema.sh SCHEMA FORMAT_DOC SCENES_DIR
set -u
schema=$1
doc=$2
scenes=$3
if ! python3 -c "import jsonschema" 2>/dev/null; then
    echo "skipped: python3 -c 'import jsonschema' failed (apt-get install python3-jsonschema)"
    exit 77
fi
python3 - "$schema" "$doc" "$scenes" <<'PY'
import glob, json, re, sys
import jsonschema

schema_file, doc_file, scenes_dir = sys.argv[1:4]
schema = json.load(open(schema_file, encoding="utf-8"))
jsonschema.Draft202012Validator.check_schema(schema)
validator = jsonschema.Draft202012Validator(schema)
failures = 0

def check(label, scene, valid, against=validator):
    global failures
    errors = sorted(against.iter_errors(scene), key=lambda e: list(e.path))
    if bool(errors) == valid:
        failures += 1
        why = "; ".join("/" + "/".join(map(str, e.path)) + ": " + e.message for e in errors[:3])
        print("FAIL:", label, "is valid" if not valid else "is not valid: " + why)
    else:
        print("ok:  ", label, "valid" if valid else "refused")

files = sorted(glob.glob(scenes_dir + "/*.json"))
for f in files:
    check(f, json.load(open(f, encoding="utf-8")), True)
# A block preceded by <!-- path3 --> is a 3-D path object, not a scene.
blocks, blocks3 = [], []
for m in re.finditer(r"(<!-- path3 -->\n)?```json\n(.*?)```", open(doc_file, encoding="utf-8").read(), re.S):
    (blocks3 if m.group(1) else blocks).append(m.group(2))
for i, text in enumerate(blocks):
    check(doc_file + " example " + str(i + 1), json.loads(text), True)
if len(files) < 7 or len(blocks) < 2:
    print("FAIL: expected at least 7 scenes and 2 examples, found", len(files), "and", len(blocks))
    failures += 1

line = {"kind": "linear", "start": [0, 0], "end": [1, 0]}
anim = {"name": "a", "path": line, "duration": 1}
def timeline(*children):
    return {"animations": [anim], "timelines": [{"name": "t", "children": list(children)}]}
check("a timeline child with a position", timeline({"animation": "a", "at": "<+0.5"}), True)
check("an animation with a repeat delay", {"animations": [dict(anim, repeat_delay=0.5)]}, True)
check("a misspelt animation field", {"animations": [dict(anim, durtion=1)]}, False)
check("a child of two kinds", timeline({"animation": "a", "label": "x"}), False)
check("a child of no kind", timeline({"at": 1}), False)
check("a position that is neither number nor string", timeline({"animation": "a", "at": [1]}), False)
check("a negative gap", timeline({"gap": -1}), False)
check("a timeline without children", {"timelines": [{"name": "t"}]}, False)
check("a time scale of 0", {"timelines": [{"name": "t", "time_scale": 0, "children": []}]}, False)
prop = {"name": "x", "value": 0}
def tweens(*ts, props=(prop,)):
    return {"properties": list(props), "tweens": list(ts)}
check("a tween to a value, and one by an amount", tweens({"property": "x", "to": 1, "duration": 1}, {"property": "x", "by": 1, "duration": 1}), True)
check("a tween placed in a timeline", dict(tweens({"name": "t", "property": "x", "to": 1, "duration": 1}),
      timelines=[{"name": "l", "children": [{"tween": "t", "at": 0.5}]}]), True)
check("a tween with both to and by", tweens({"property": "x", "to": 1, "by": 1, "duration": 1}), False)
check("a tween with from and by", tweens({"property": "x", "from": 0, "by": 1, "duration": 1}), False)
check("a tween with neither to nor by", tweens({"property": "x", "duration": 1}), False)
check("a colour property", tweens(props=({"name": "c", "type": "color", "value": "#ff8000", "space": "oklab"},)), True)
check("a colour space on a number", tweens(props=({"name": "x", "value": 0, "space": "oklab"},)), False)
check("a vec2 property holding a number", tweens(props=({"name": "p", "type": "vec2", "value": 0},)), False)
check("a turn on a vec2", tweens(props=({"name": "p", "type": "vec2", "value": [0, 0], "turn": "every"},)), False)
check("vec3 and quat properties with tweens", tweens({"property": "v", "from": [0, 0, 0], "to": [1, 2, 3], "duration": 1},
      {"property": "v", "by": [1, 0, 0], "duration": 1}, {"property": "q", "to": [0, 0, 0, 1], "duration": 1},
      props=({"name": "v", "type": "vec3", "value": [0, 0, 1]}, {"name": "q", "type": "quat", "value": [1, 0, 0, 0]})), True)
check("a vec3 property holding a vec2", tweens(props=({"name": "v", "type": "vec3", "value": [0, 0]},)), False)
check("a quat property holding three numbers", tweens(props=({"name": "q", "type": "quat", "value": [1, 0, 0]},)), False)
# 3-D path objects (the schema's $defs/path3): the format's examples marked <!-- path3 -->.
path3 = jsonschema.Draft202012Validator({"$schema": schema["$schema"], "$defs": schema["$defs"], "$ref": "#/$defs/path3"})
for i, text in enumerate(blocks3):
    check(doc_file + " 3-D path example " + str(i + 1), json.loads(text), True, path3)
if len(blocks3) < 2:
    print("FAIL: expected at least 2 3-D path examples, found", len(blocks3))
    failures += 1
line3 = {"kind": "line", "points": [[0, 0, 0], [1, 2, 3]]}
check("a 3-D complex path of a line and a nested complex path",
      {"kind": "complex", "parts": [line3, {"kind": "complex", "parts": [line3]}], "cues": [0, 0.5]}, True, path3)
check("a 3-D line with a 2-D point", {"kind": "line", "points": [[0, 0], [1, 2, 3]]}, False, path3)
check("a 3-D line with three points", {"kind": "line", "points": [[0, 0, 0], [1, 2, 3], [4, 5, 6]]}, False, path3)
check("a misspelt 3-D field", {"kind": "helix", "center": [0, 0, 0], "axis": [0, 0, 1], "start": [1, 0, 0],
                               "radius": 1, "turns": 1, "rise": 2}, False, path3)
check("a 3-D kind of the 2-D paths", {"kind": "linear", "start": [0, 0, 0], "end": [1, 0, 0]}, False, path3)
check("a Catmull-Rom alpha of 0.25", {"kind": "catmull-rom", "points": [[0, 0, 0], [1, 0, 0]], "alpha": 0.25}, False, path3)
check("a helix without a radius", {"kind": "helix", "center": [0, 0, 0], "axis": [0, 0, 1], "start": [1, 0, 0],
                                   "turns": 1}, False, path3)
check("a 2-D path on a plane", {"kind": "on_plane", "path": {"kind": "circle", "center": [0, 0], "radius": 1},
                                "origin": [0, 0, 0], "x_axis": [1, 0, 0], "y_axis": [0, 0, 1]}, True, path3)
check("a 2-D path name on a plane", {"kind": "on_plane", "path": "track", "origin": [0, 0, 0], "x_axis": [1, 0, 0],
                                     "y_axis": [0, 0, 1]}, False, path3)
check("a projectile without seconds", {"kind": "projectile", "position": [0, 0, 0], "velocity": [1, 0, 0],
                                       "acceleration": [0, 0, -9.8]}, False, path3)
# 3-D animations: duration or speed, a frame, roll or bank, placed in timelines as animation3.
anim3 = {"name": "c", "path": line3, "speed": 2, "align": "frame", "frame": {"mode": "up", "up": [0, 0, 1]}}
check("a 3-D animation in a timeline", {"animations3": [anim3], "timelines": [{"name": "t", "children": [{"animation3": "c"}]}]}, True)
check("a 3-D animation on a named 3-D path", {"paths3": [{"name": "l", "path": line3}],
      "animations3": [dict(anim3, path="l", bank={"speed": 3})]}, True)
check("a 3-D animation with duration and speed", {"animations3": [dict(anim3, duration=1)]}, False)
check("a 3-D animation with neither duration nor speed", {"animations3": [{"path": line3}]}, False)
check("a 3-D animation with roll and bank", {"animations3": [dict(anim3, roll=[[0, 1]], bank={"speed": 3})]}, False)
check("a misspelt 3-D animation field", {"animations3": [dict(anim3, allign="frame")]}, False)
check("a 3-D animation with an unknown axis", {"animations3": [dict(anim3, axes={"forward": "z"})]}, False)
check("a 3-D animation with a 2-D path", {"animations3": [dict(anim3, path=line)]}, False)
sys.exit(1 if failures else 0)
PY
