#!/usr/bin/env python3
"""Checks the query tables of docs/API.md against the shape and pair tables (src/query/pairs2.h,
src/query/pairs3.h), which drive the dispatchers and the matrix tests.

Usage: check_api_table.py [SOURCE_DIR]   (default: the parent of this script's folder)

For each dimension N (2, 3):
  * every pair row's typed overlap function (the Overlap column, unless GJK) is named in the
    "## ND matrix" section, and every cdNOverlap<A><B> named there is a row of the pair table;
  * every pair row's typed manifold function (the Collide column, unless CORE or NONE) is named in
    the "## ND contact manifolds" section, and every cdNCollide<A><B> named there is a row's (or,
    if public, the mirror of a row's, such as cd2CollidePolygonCircle);
  * the Distance column: `cdNDistance` is named in the matrix section (it serves every pair); a
    CLOSED_FORM distance whose cdNClosestPoints<A><B> is public is named there, and every
    cdNClosestPoints<A><B> named there is a CLOSED_FORM row's; a named closed-form distance
    (two circles, two spheres) is said there as "two <shape>s in closed form", and every such
    phrase there is a named distance row's;
  * the Collide column: every typed manifold has its public ...Local form, and a CORE row (only
    the generic dispatcher handles the pair) needs `cdNCollide` named in the manifold section;
  * every public PointIn / ClosestPointOn / Raycast function of a shape row is named in API.md, and
    every cdNPointIn<Shape> / cdNClosestPointOn<Shape> / cdNRaycast<Shape> named in the matrix
    section is its shape row's;
  * the "argument order" rule lists the shape types in the order of the shape table.
"Public" means declared with CD_API in include/collide/*.h. A name written with braces,
`cd3ClosestPointOn{Sphere,Capsule}`, names each member. The check fails with the row to add or
remove; adding a shape or a pair (CONTRIBUTING.md, "Adding a shape") therefore means adding its
line to the docs too.
"""
import os
import re
import sys


def table_rows(text, macro):
    """The argument lists of the X(...) rows of `#define macro(X)`."""
    start = text.find("#define %s(X)" % macro)
    if start < 0:
        raise SystemExit("check_api_table: no #define %s(X)" % macro)
    body = []
    for line in text[start:].splitlines()[1:]:
        body.append(line.rstrip().rstrip("\\"))
        if not line.rstrip().endswith("\\"):
            break
    body = " ".join(body)
    rows = []
    i = 0
    while True:
        i = body.find("X(", i)
        if i < 0:
            return rows
        depth, j = 0, i + 1
        while True:
            if body[j] == "(":
                depth += 1
            elif body[j] == ")":
                depth -= 1
                if depth == 0:
                    break
            j += 1
        rows.append([arg.strip() for arg in body[i + 2:j].split(",")])
        i = j


def expand_names(token):
    """`cd3ClosestPointOn{Sphere,Capsule}` -> [cd3ClosestPointOnSphere, cd3ClosestPointOnCapsule]."""
    m = re.fullmatch(r"(\w*)\{([\w,\s]+)\}(\w*)", token)
    if m:
        return [m.group(1) + part.strip() + m.group(3) for part in m.group(2).split(",")]
    return [token] if re.fullmatch(r"\w+", token) else []


def doc_names(markdown):
    """Names in backticks (the function part of a call: `cd2Collide(a, b, d)` -> cd2Collide)."""
    names = set()
    for token in re.findall(r"`([^`]+)`", markdown):
        token = token.split("(")[0].strip()
        names.update(expand_names(token))
    return names


def sections(markdown):
    out, current = {}, None
    for line in markdown.splitlines():
        if line.startswith("## "):
            current = line[3:].strip()
            out[current] = []
        elif current is not None:
            out[current].append(line)
    return {k: "\n".join(v) for k, v in out.items()}


def public_functions(include_dir):
    names = set()
    for name in sorted(os.listdir(include_dir)):
        if name.endswith(".h"):
            with open(os.path.join(include_dir, name), encoding="utf-8") as f:
                text = f.read()
            names.update(re.findall(r"CD_API[^;(]*?\b(cd\w+)\s*\(", text, re.S))
    return names


def check_dimension(n, pairs_text, api, public, errors):
    shape_rows = table_rows(pairs_text, "CD%d_SHAPE_TABLE" % n)
    pair_rows = table_rows(pairs_text, "CD%d_PAIR_TABLE" % n)
    if n == 3:
        pair_rows += table_rows(pairs_text, "CD3_HULL_PAIR_TABLE")
    shapes = [row[0] for row in shape_rows]
    sec = sections(api)
    matrix_key = "%dD matrix" % n
    manifold_key = "%dD contact manifolds" % n
    for key in (matrix_key, manifold_key):
        if key not in sec:
            errors.append("docs/API.md: no section '## %s'" % key)
            return
    matrix = doc_names(sec[matrix_key])
    manifolds = doc_names(sec[manifold_key])
    everywhere = doc_names(api)
    prefix = "cd%d" % n
    shape_alt = "|".join(shapes)

    overlaps = {row[2] for row in pair_rows if row[2] != "GJK"}
    collides = {row[4] for row in pair_rows if row[4] not in ("CORE", "NONE")}
    for row in pair_rows:
        a, b, overlap, distance, collide = row
        pair = "%s-%s" % (a.lower(), b.lower())
        if overlap != "GJK" and overlap not in matrix:
            errors.append("docs/API.md '## %s': no row for the %s overlap: add `| %s | `%s` | ... |`"
                          % (matrix_key, pair, pair, overlap))
        if collide not in ("CORE", "NONE") and collide not in manifolds:
            errors.append("docs/API.md '## %s': `%s` (pair %s) is not named" % (manifold_key, collide, pair))
        closest = "%sClosestPoints%s%s" % (prefix, a, b)
        if distance == "CLOSED_FORM" and closest in public and closest not in matrix:
            errors.append("docs/API.md '## %s': `%s` (closed-form distance of %s) is not named"
                          % (matrix_key, closest, pair))
    # The Distance column.
    if "%sDistance" % prefix not in matrix:
        errors.append("docs/API.md '## %s': the dispatcher `%sDistance` (every pair's distance) is not named"
                      % (matrix_key, prefix))
    closed_pairs = {"%sClosestPoints%s%s" % (prefix, row[0], row[1]) for row in pair_rows if row[3] == "CLOSED_FORM"}
    for name in sorted(matrix):
        if re.fullmatch(r"%sClosestPoints(%s)(%s)" % (prefix, shape_alt, shape_alt), name) and name not in closed_pairs:
            errors.append("docs/API.md '## %s': `%s` is not a CLOSED_FORM distance of the pair table (pairs%d.h)"
                          % (matrix_key, name, n))
    matrix_text = " ".join(sec[matrix_key].split())
    named_distances = {row[0].lower() for row in pair_rows
                       if row[3] not in ("GJK", "CLOSED_FORM") and row[0] == row[1]}
    for row in pair_rows:
        if row[3] not in ("GJK", "CLOSED_FORM") and row[0] != row[1]:
            errors.append("src/query/pairs%d.h: the closed-form distance %s of %s-%s: only same-shape pairs "
                          "have one (extend check_api_table.py for others)" % (n, row[3], row[0], row[1]))
    for shape in sorted(named_distances):
        if ("two %ss in closed form" % shape) not in matrix_text:
            errors.append("docs/API.md '## %s': the closed-form distance of two %ss (pairs%d.h) is not said "
                          "(\"two %ss in closed form\")" % (matrix_key, shape, n, shape))
    for shape in re.findall(r"two (\w+)s in closed form", matrix_text):
        if shape not in named_distances:
            errors.append("docs/API.md '## %s': \"two %ss in closed form\" but the pair table's %s-%s row "
                          "has no closed-form distance" % (matrix_key, shape, shape, shape))
    # The Collide column.
    for name in sorted(collides):
        if name + "Local" not in public:
            errors.append("include/collide: `%sLocal` (the local-frame form of %s) is not public" % (name, name))
    if any(row[4] == "CORE" for row in pair_rows) and "%sCollide" % prefix not in manifolds:
        errors.append("docs/API.md '## %s': `%sCollide` (the pairs the table marks CORE) is not named"
                      % (manifold_key, prefix))

    for name in sorted(matrix):
        if re.fullmatch(r"%sOverlap(%s)(%s)" % (prefix, shape_alt, shape_alt), name) and name not in overlaps:
            errors.append("docs/API.md '## %s': `%s` is not a row of the pair table (pairs%d.h)"
                          % (matrix_key, name, n))
    for name in sorted(manifolds):
        match = re.fullmatch(r"%sCollide(%s)(%s)" % (prefix, shape_alt, shape_alt), name)
        # A public form out of canonical order (cd2CollidePolygonCircle) mirrors a row's function.
        mirrored = (match is not None and name in public
                    and "%sCollide%s%s" % (prefix, match.group(2), match.group(1)) in collides)
        if match is not None and name not in collides and not mirrored:
            errors.append("docs/API.md '## %s': `%s` is not a typed manifold of the pair table (pairs%d.h)"
                          % (manifold_key, name, n))

    columns = {"PointIn": 1, "ClosestPointOn": 2, "Raycast": 3}
    for row in shape_rows:
        for column, index in columns.items():
            function = row[index]
            if function in public and function not in everywhere:
                errors.append("docs/API.md: `%s` (the %s of the %s row) is not named" % (function, column, row[0]))
    for column, index in columns.items():
        listed = {row[index] for row in shape_rows}
        for name in sorted(matrix):
            if re.fullmatch(r"%s%s(%s)" % (prefix, column, shape_alt), name) and name not in listed:
                errors.append("docs/API.md '## %s': `%s` is not the %s of a shape row" % (matrix_key, name, column))

    order = re.search(r"%dD: ([A-Za-z, ]+)[;)]" % n, api)
    if not order:
        errors.append("docs/API.md: the argument-order rule does not list the %dD shape types" % n)
    elif [s.strip() for s in order.group(1).split(",")] != shapes:
        errors.append("docs/API.md: the %dD argument order '%s' differs from the shape table's: %s"
                      % (n, order.group(1), ", ".join(shapes)))
    return len(pair_rows), len(shape_rows)


def main():
    root = sys.argv[1] if len(sys.argv) > 1 else os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    with open(os.path.join(root, "docs", "API.md"), encoding="utf-8") as f:
        api = f.read()
    public = public_functions(os.path.join(root, "include", "collide"))
    errors = []
    counts = []
    for n in (2, 3):
        with open(os.path.join(root, "src", "query", "pairs%d.h" % n), encoding="utf-8") as f:
            result = check_dimension(n, f.read(), api, public, errors)
        if result:
            counts.append("%dD: %d shapes, %d pairs" % (n, result[1], result[0]))
    for error in errors:
        print(error)
    if errors:
        print("check_api_table: %d mismatch(es) between docs/API.md and src/query/pairs2.h / pairs3.h" % len(errors))
        return 1
    print("check_api_table: docs/API.md agrees with the tables (%s)" % "; ".join(counts))
    return 0


if __name__ == "__main__":
    sys.exit(main())
