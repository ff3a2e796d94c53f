#!/usr/bin/env python3
"""Checks every exported name of the public headers against the naming rule of CONTRIBUTING.md.

Usage: check_names.py [INCLUDE_DIR]   (default: include/collide next to this script's parent)

The rule (CONTRIBUTING.md, "Naming"):
  * prefix cd (both dimensions), cd2 (2D) or cd3 (3D); types PascalCase after the prefix, no '_';
    enum constants and macros CD_UPPER_SNAKE (CD2_ / CD3_ for one dimension);
  * functions prefix + VerbNoun, the verb from VERBS or a query family from FAMILIES; objects are
    made by cdNCreateX and freed by cdNDestroyX;
  * everything else on an object handle is prefix + Type_Verb (cd3Mesh_QueryAabb): a function whose
    first parameter points to a handle is a method unless it is a lifecycle function (Destroy,
    Validate) or a query of a family (cd3RaycastMesh(mesh, ...), cd2CollideChain(chain, ...));
  * the ray-cast verb is spelled Raycast, never RayCast;
  * pair functions name their shapes in the order of the shape-type enum (manifolds included);
    chain segments and meshes are not shape types and come first.
  * static inline helpers of math2.h, math3.h and base.h are the math vocabulary (cd2Add, cdSqrt):
    only their prefix is checked; other static inline helpers may also be named
    prefix + ValueType + Operation (cd2AabbUnion).

Exceptions are listed below with their reason. A name that breaks the rule and is not listed fails
the check, so a new exception needs a line here and a reason.
"""
import os
import re
import sys

VERBS = [
    "Make", "Compute", "Create", "Destroy", "Validate", "IsValid", "Is", "Get", "Set", "Default",
    "Alloc", "Free", "Transform", "Inv", "Mul", "Query", "Find", "Update", "Move", "Rebuild",
    "Clip", "Solve",
]
# Query families: the generic dispatchers and their pair functions are named after them.
FAMILIES = [
    "Overlap", "PointIn", "ClosestPointOn", "ClosestPoints", "Raycast", "Distance", "Collide",
    "ShapeCast", "TimeOfImpact",
]
VALUE_TYPES = ["Aabb", "Vec", "Rot", "Quat", "Mat22", "Mat33", "Transform", "Manifold",
               "WorldId", "BodyId", "ShapeId", "JointId", "ChainId"]
MATH_HEADERS = {"math2.h", "math3.h", "base.h"}

# name -> reason. Keep this list short: every line is a name users must learn as an exception.
EXCEPTIONS = {
    "cd3ComputeHull": "creates a cd3Hull (spelled by the hull API's contract: Compute, as in computing a convex hull)",
    "cd3MakeBoxHull": "creates a cd3Hull (spelled by the hull API's contract)",
    "cd3MakeCylinderHull": "creates a cd3Hull (spelled by the hull API's contract)",
    "cd3MakeConeHull": "creates a cd3Hull (the family of cd3MakeBoxHull)",
    "cdInternalAssert": "called by the CD_ASSERT macro only",
    "cd3CollideHullTriangle": "former order of cd3CollideTriangleHull, kept for one release",
    "cd2CollidePolygonCircle": "the mirror of cd2CollideCirclePolygon with the polygon as A (normal from the polygon)",
    "cd2CollidePolygonCircleLocal": "the polygon-first local form: only the circle's centre is placed, nothing mapped back",
}
# Creators of objects that are not spelled cdNCreateX (see EXCEPTIONS).
CREATORS = {"cd3Hull": ["cd3ComputeHull", "cd3MakeBoxHull", "cd3MakeCylinderHull", "cd3MakeConeHull"]}
# Former names, kept as alias macros for one release (each header's "Former names" block).
FORMER_NAMES = {
    "cd2BroadPhase_Create": "cd2CreateBroadPhase",
    "cd2BroadPhase_Destroy": "cd2DestroyBroadPhase",
    "cd3BroadPhase_Create": "cd3CreateBroadPhase",
    "cd3BroadPhase_Destroy": "cd3DestroyBroadPhase",
    "cd2BroadPhase_RayCast": "cd2BroadPhase_Raycast",
    "cd3BroadPhase_RayCast": "cd3BroadPhase_Raycast",
    "cdBroadPhaseTypeName": "cdGetBroadPhaseTypeName",
    "cd3GetMeshStats": "cd3Mesh_GetStats",
    "cd3GetMeshTriangleCount": "cd3Mesh_GetTriangleCount",
    "cd3GetMeshTriangle": "cd3Mesh_GetTriangle",
    "cd3GetHullTolerance": "cd3Hull_GetTolerance",
    "cd3ShapeTypeName": "cd3GetShapeTypeName",
    "cd2ShapeTypeName": "cd2GetShapeTypeName",
    "cd2GetChainSegmentCount": "cd2Chain_GetSegmentCount",
    "cd2GetChainPointCount": "cd2Chain_GetPointCount",
    "cd2GetChainPoints": "cd2Chain_GetPoints",
    "cd2IsChainLoop": "cd2Chain_IsLoop",
    "cd2GetChainBounds": "cd2Chain_GetBounds",
    "cd2GetChainSegment": "cd2Chain_GetSegment",
    "cdResultString": "cdGetResultString",
}


def strip_comments(text):
    text = re.sub(r"/\*.*?\*/", lambda m: "\n" * m.group(0).count("\n"), text, flags=re.S)
    return re.sub(r"//[^\n]*", "", text)


def parse(include_dir):
    functions = {}  # name -> (header, kind, first parameter text)
    types, macros, constants = {}, {}, {}
    shape_enums = {}
    for header in sorted(os.listdir(include_dir)):
        if not header.endswith(".h"):
            continue
        text = strip_comments(open(os.path.join(include_dir, header), encoding="utf-8").read())
        code = re.sub(r"^\s*#[^\n]*", "", text, flags=re.M)  # declarations, without preprocessor lines
        for m in re.finditer(r"CD_API\s+[^;{()]*?\b(\w+)\s*\(([^)]*)\)", code):
            functions[m.group(1)] = (header, "api", m.group(2).split(",")[0].strip())
        for m in re.finditer(r"static\s+inline\s+[^;{()]*?\b(\w+)\s*\(([^)]*)\)", code):
            functions[m.group(1)] = (header, "inline", m.group(2).split(",")[0].strip())
        for m in re.finditer(r"^\s*#\s*define\s+(\w+)", text, flags=re.M):
            macros[m.group(1)] = header
        for m in re.finditer(r"\}\s*(\w+)\s*;", text):
            types[m.group(1)] = header
        for m in re.finditer(r"typedef\s+struct\s+(\w+)\s+(\w+)\s*;", text):
            types[m.group(2)] = header + " (opaque)"
        for m in re.finditer(r"typedef\s+[\w\s\*]+?\b(\w+)\s*\(", text):
            types[m.group(1)] = header
        for m in re.finditer(r"typedef\s+(?:float|double)\s+(\w+)\s*;", text):
            types[m.group(1)] = header
        for m in re.finditer(r"typedef\s+enum\s+\w*\s*\{([^}]*)\}\s*(\w+)\s*;", text):
            names = [re.match(r"\s*(\w+)", e).group(1) for e in m.group(1).split(",") if e.strip()]
            for n in names:
                constants[n] = header
            if m.group(2) in ("cd2ShapeType", "cd3ShapeType"):
                shape_enums[m.group(2)[:3]] = [
                    "".join(w.capitalize() for w in n.split("_")[2:]) for n in names if not n.endswith("_COUNT")
                ]
    return functions, types, macros, constants, shape_enums


def split_prefix(name):
    m = re.match(r"^(cd[23]?)([A-Z]\w*)$", name)
    return (m.group(1), m.group(2)) if m else (None, None)


def starts_with_word(rest, words):
    for w in sorted(words, key=len, reverse=True):
        if rest.startswith(w) and (len(rest) == len(w) or not rest[len(w)].islower()):
            return w
    return None


def shape_tokens(rest, shapes):
    """rest split into shape names, or None when it is not only shapes (then it is no pair)."""
    out = []
    while rest:
        w = starts_with_word(rest, shapes)
        if w is None:
            return None
        out.append(w)
        rest = rest[len(w):]
    return out


def check(include_dir):
    functions, types, macros, constants, shape_enums = parse(include_dir)
    errors = []
    handles = {t for t, h in types.items() if h.endswith("(opaque)")}
    for name, (_, _, first) in functions.items():
        # cdNDestroyX(X*) frees a handle X; cdNDestroyX(XId) destroys an object known by an id
        # (the worlds' bodies, shapes, joints), whose methods are cdNX_Verb(XId, ...).
        m = re.match(r"^(cd[23]?)Destroy(\w+)$", name)
        if m and re.match(r"^(?:const\s+)?" + m.group(1) + m.group(2) + r"\s*\*", first):
            handles.add(m.group(1) + m.group(2))
    created = {m.group(1) + m.group(2) for m in (re.match(r"^(cd[23]?)Create(\w+)$", f) for f in functions) if m}

    for name, header in types.items():
        if not re.match(r"^cd[23]?[A-Z][A-Za-z0-9]*$", name):
            errors.append(f"type {name} ({header}): cd/cd2/cd3 + PascalCase, no '_'")
    for name, header in list(macros.items()) + list(constants.items()):
        if name in FORMER_NAMES:
            continue
        if re.match(r"^COLLIDE_[A-Z0-9_]+_H$", name) or name in ("CD_API",):
            continue
        if not re.match(r"^CD[23]?_[A-Z0-9_]+$", name):
            errors.append(f"macro or constant {name} ({header}): CD_UPPER_SNAKE")
    for name in FORMER_NAMES:
        if name not in macros:
            errors.append(f"former name {name} is listed but has no alias macro: drop it from FORMER_NAMES")
        elif FORMER_NAMES[name] not in functions:
            errors.append(f"former name {name} aliases {FORMER_NAMES[name]}, which does not exist")

    for name, (header, kind, first) in sorted(functions.items()):
        if name in EXCEPTIONS:
            continue
        prefix, rest = split_prefix(name)
        if prefix is None:
            errors.append(f"function {name} ({header}): prefix cd, cd2 or cd3 followed by a capital")
            continue
        if "RayCast" in name:
            errors.append(f"function {name} ({header}): the verb is spelled Raycast")
        if kind == "inline" and header in MATH_HEADERS:
            continue
        if "_" in rest:
            handle, verb = rest.split("_", 1)
            if not re.match(r"^[A-Z][A-Za-z0-9]*$", handle) or not re.match(r"^[A-Z][A-Za-z0-9]*$", verb):
                errors.append(f"method {name} ({header}): prefix + Type_Verb, both PascalCase")
            elif prefix + handle not in types and prefix + handle + "Id" not in types and prefix + handle not in created:
                errors.append(f"method {name} ({header}): {prefix + handle} is not a public type")
            elif verb in ("Create", "Destroy"):
                errors.append(f"method {name} ({header}): objects are made and freed by {prefix}{verb}{handle}")
            continue
        lead = starts_with_word(rest, VERBS + FAMILIES)
        if lead is None and kind == "inline" and starts_with_word(rest, VALUE_TYPES):
            continue
        if lead is None:
            errors.append(f"function {name} ({header}): prefix + VerbNoun (verbs: {', '.join(VERBS)}; "
                          f"query families: {', '.join(FAMILIES)})")
            continue
        # A function on a handle that is neither lifecycle nor a query family is a method.
        fm = re.match(r"^(?:const\s+)?(cd[23]?\w+)\s*\*", first)
        if fm and fm.group(1) in handles and lead not in FAMILIES + ["Destroy", "Validate", "Make"]:
            errors.append(f"function {name} ({header}) works on a {fm.group(1)}: name it "
                          f"{prefix}{fm.group(1)[len(prefix):]}_Verb")
        if lead == "Destroy":
            obj = prefix + rest[len("Destroy"):]
            creators = [f for f in functions if re.match(r"^" + prefix + r"Create\w*" + rest[len("Destroy"):] + r"$", f)]
            if not creators and not CREATORS.get(obj):
                errors.append(f"function {name} ({header}): no {prefix}Create{rest[len('Destroy'):]}")
        # Pair order.
        fam = starts_with_word(rest, ["Overlap", "Collide", "ClosestPoints", "Distance"])
        shapes = shape_enums.get(prefix)
        if fam and shapes:
            tail = rest[len(fam):]
            if tail.endswith("Local"):
                tail = tail[: -len("Local")]
            tokens = shape_tokens(tail, shapes)
            if tokens and len(tokens) == 2 and shapes.index(tokens[0]) > shapes.index(tokens[1]):
                errors.append(f"pair function {name} ({header}): shapes in the order of {prefix}ShapeType "
                              f"({', '.join(shapes)}): {prefix}{fam}{tokens[1]}{tokens[0]}")
    return functions, errors


def check_former_names_doc(api_path, errors):
    """docs/API.md's "## Former names" table lists exactly FORMER_NAMES (the note users read)."""
    if not os.path.exists(api_path):
        return
    with open(api_path, encoding="utf-8") as f:
        text = f.read()
    start = text.find("\n## Former names")
    if start < 0:
        errors.append("docs/API.md: no '## Former names' section listing the renamed functions")
        return
    end = text.find("\n## ", start + 1)
    section = text[start:end if end >= 0 else len(text)]
    listed = dict(re.findall(r"^\|\s*`(\w+)`\s*\|\s*`(\w+)`\s*\|", section, re.M))
    for old, new in FORMER_NAMES.items():
        if listed.get(old) != new:
            errors.append(f"docs/API.md '## Former names': add the row | `{old}` | `{new}` |")
    for old in listed:
        if old not in FORMER_NAMES:
            errors.append(f"docs/API.md '## Former names': `{old}` is not in FORMER_NAMES (no alias macro)")


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    include_dir = sys.argv[1] if len(sys.argv) > 1 else os.path.join(here, "..", "include", "collide")
    functions, errors = check(include_dir)
    check_former_names_doc(os.path.join(include_dir, "..", "..", "docs", "API.md"), errors)
    for e in errors:
        print("check_names: " + e)
    print(f"check_names: {len(functions)} functions checked, {len(EXCEPTIONS)} listed exceptions, "
          f"{len(FORMER_NAMES)} former names, {len(errors)} errors")
    return 1 if errors else 0


if __name__ == "__main__":
    sys.exit(main())
