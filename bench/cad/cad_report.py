# SPDX-License-Identifier: MIT
"""docs/results/cad.md from the results run_cad_bench.py gathers (results.json)."""

import math

DEFECTS = (  # check --json key, how the table names it
    ("border_edges", "border edges"),
    ("cracks", "crack edges"),
    ("t_junctions", "T-junctions"),
    ("non_manifold_edges", "non-manifold edges"),
    ("non_manifold_vertices", "non-manifold vertices"),
    ("degenerate_triangles", "degenerate"),
    ("duplicated_triangles", "duplicated"),
    ("inconsistent_orientation", "misoriented pairs"),
    ("self_intersections", "self-intersections"),
)


def count(js, key):
    v = js.get(key, 0)
    return v.get("count", 0) if isinstance(v, dict) else v


def verdict(check):
    """'PASS', 'FAIL: ...' or the check's own failure."""
    if not check:
        return ""
    if "error" in check:
        return "check failed: " + check["error"]
    parts = ["%d %s" % (count(check, k), name) for k, name in DEFECTS if count(check, k)]
    contact = contacts(check)
    if check.get("passed"):
        return "PASS" + contact
    if check.get("defects", 1) == 0:  # fails --closed only: an open surface or shell
        return "open (%d border edges), no defect%s" % (count(check, "border_edges"), contact)
    return "FAIL: " + ", ".join(parts) + contact


def contacts(check):
    """'' or '; 3 of 18 solids in contact' (solids judged apart, touching: not a defect)."""
    pairs = check.get("body_contacts", {}).get("listed", [])
    if not pairs:
        return ""
    touching = {b for p in pairs for b in p["bodies"]}
    return "; %d of %d %s in contact" % (len(touching), check.get("body_count", 0),
                                         check.get("bodies", "solids"))


def num(x, digits=3):
    if x is None:
        return "-"
    if x == 0:
        return "0"
    return "%.*g" % (digits, x)


def seconds(run):
    return run.get("mesh_seconds") if run and run.get("ok") else None


def deviation(side, D):
    """(face->mesh, mesh->face) in units of D, or None."""
    dev = side.get("deviation") or {}
    if "face_to_mesh" not in dev:
        return None
    return dev["face_to_mesh"]["max"] / D, dev["mesh_to_face"]["max"] / D


def tool_row(row, entry, tool):
    side = entry[tool]
    r1, r2 = side["run1"], side.get("run2", {})
    label = "seamless" if tool == "seamless" else "OpenCASCADE"
    if not r1.get("ok"):
        return "| | | %s | **failed**: %s | | | | | | | | |" % (
            label, r1.get("error", "").replace("|", "/"))
    dev = deviation(side, entry["D"])
    dev_error = (side.get("deviation") or {}).get("error", "")
    if dev:
        dev_cells = "%s | %s" % (num(dev[0], 2), num(dev[1], 2))
    else:
        # Without a model read by seamless there is no B-rep to measure against.
        why = "timeout" if "timeout" in dev_error else "not read"
        dev_cells = "n/a (%s) | n/a" % why
    unmeshed = r1.get("unmeshed_faces", 0) if tool == "occt" else 0
    read = row.get("occt_read_seconds") if tool == "occt" else r1.get("other_seconds")
    return "| | | %s | %s | %s | %s | %d | %s | %s | %s | %s |" % (
        label, "meshed" if not unmeshed else "holes", unmeshed,
        verdict(side.get("check")), r1["triangles"], dev_cells, num(seconds(r1)),
        num(seconds(r2)), num(read))


def level_table(results, level):
    key = repr(level)
    lines = ["## D = %g x diagonal" % level, "",
             "Deviation columns: the measured maximum in units of D (<= 1 meets the request). "
             "Read: OpenCASCADE's reading alone; for seamless the rest of the process's wall "
             "time (reading, writing, start-up, and the certified bound that `--stats` computes).", "",
             "| file | faces | tool | result | unmeshed | check --closed | triangles | "
             "face->mesh / D | mesh->face / D | 1 thread (s) | 2 threads (s) | read (s) |",
             "|---|---:|---|---|---:|---|---:|---:|---:|---:|---:|---:|"]
    for row in results["rows"]:
        if "error" in row:
            lines.append("| %s | | | **%s** | | | | | | | | |" % (row["name"], row["error"]))
            continue
        entry = row["levels"].get(key)
        if entry is None:
            continue
        lines.append("| %s | %d | D = %s | | | | | | | | | |" % (row["name"], row["faces"],
                                                                 num(entry["D"])))
        for tool in ("seamless", "occt"):
            lines.append(tool_row(row, entry, tool))
    return lines


def closed_solid(entry):
    """Whether seamless read the model as solids whose shells are all closed."""
    for tool in ("seamless", "occt"):
        dev = entry[tool].get("deviation") or {}
        if "shells" in dev:
            return dev.get("solids", 0) > 0 and dev["closed_shells"] == dev["shells"]
    return False


def summary(results, level):
    """Figures for the goals at one level."""
    key = repr(level)
    s = {"files": 0, "seamless_ok": 0, "occt_ok": 0, "occt_complete": 0, "seamless_pass": 0,
         "occt_pass": 0, "within_D": 0, "measured": 0, "ratios": [], "both": 0,
         "t1": [0.0, 0.0], "t2": [0.0, 0.0], "worst_dev": 0.0, "solids": 0,
         "solids_pass": 0, "seamless_sound": 0, "occt_sound": 0, "occt_within_D": 0,
         "occt_measured": 0, "occt_worst_dev": 0.0, "within_gap": 0, "gapped": 0,
         "brep_ratios": [], "surface_ratios": []}
    for row in results["rows"]:
        s["files"] += 1
        entry = row.get("levels", {}).get(key)
        if not entry:
            continue
        ours, occ = entry["seamless"], entry["occt"]
        ok_ours, ok_occ = ours["run1"].get("ok"), occ["run1"].get("ok")
        s["seamless_ok"] += bool(ok_ours)
        s["occt_ok"] += bool(ok_occ)
        s["occt_complete"] += bool(ok_occ and not occ["run1"].get("unmeshed_faces"))
        s["seamless_pass"] += bool(ok_ours and (ours.get("check") or {}).get("passed"))
        s["occt_pass"] += bool(ok_occ and (occ.get("check") or {}).get("passed"))
        s["seamless_sound"] += bool(ok_ours and (ours.get("check") or {}).get("defects", 1) == 0)
        s["occt_sound"] += bool(ok_occ and (occ.get("check") or {}).get("defects", 1) == 0)
        if closed_solid(entry):
            s["solids"] += 1
            s["solids_pass"] += bool(ok_ours and (ours.get("check") or {}).get("passed"))
        dev = deviation(ours, entry["D"]) if ok_ours else None
        if dev:
            s["measured"] += 1
            s["within_D"] += max(dev) <= 1
            s["worst_dev"] = max(s["worst_dev"], max(dev))
            # The B-rep's own gap (edge curves measured off their faces):
            # no mesh of both faces is nearer than it to one of them.
            gap = gap_in_D(ours, entry["D"])
            s["gapped"] += gap > 1
            s["within_gap"] += max(dev) <= max(1, gap)
        dev = deviation(occ, entry["D"]) if ok_occ else None
        if dev:
            s["occt_measured"] += 1
            s["occt_within_D"] += max(dev) <= 1
            s["occt_worst_dev"] = max(s["occt_worst_dev"], max(dev))
        if ok_ours and ok_occ and seconds(ours.get("run2")) and seconds(occ.get("run2")):
            s["both"] += 1
            ratio = ours["run1"]["triangles"] / occ["run1"]["triangles"]
            s["ratios"].append(ratio)
            s["brep_ratios" if ours["run1"].get("brep") else "surface_ratios"].append(ratio)
            s["t1"][0] += seconds(ours["run1"])
            s["t1"][1] += seconds(occ["run1"])
            s["t2"][0] += seconds(ours["run2"])
            s["t2"][1] += seconds(occ["run2"])
    for key in ("", "brep_", "surface_"):
        r = s[key + "ratios"]
        s[key + "geomean"] = math.exp(sum(math.log(x) for x in r) / len(r)) if r else None
    return s


def gap_in_D(side, D):
    """seamless's measured B-rep gap (--stats brep.max_edge_offset) in units of D."""
    return (side["run1"].get("brep") or {}).get("max_edge_offset", 0.0) / D


def summary_table(results):
    lines = ["## Summary", "",
             "Triangles and times over the files both tools meshed (the ratio seamless / "
             "OpenCASCADE; times in seconds, meshing only).", "",
             "| | " + " | ".join("D = %g x diag" % lv for lv in results["levels"]) + " |",
             "|---|" + "---:|" * len(results["levels"])]
    sums = [summary(results, lv) for lv in results["levels"]]

    def add(label, f):
        lines.append("| %s | %s |" % (label, " | ".join(f(s) for s in sums)))

    add("files", lambda s: str(s["files"]))
    add("seamless meshed", lambda s: str(s["seamless_ok"]))
    add("OpenCASCADE meshed (all faces)", lambda s: "%d (%d)" % (s["occt_ok"], s["occt_complete"]))
    add("check: no defect (seamless / OpenCASCADE)",
        lambda s: "%d / %d" % (s["seamless_sound"], s["occt_sound"]))
    add("check --closed PASS (seamless / OpenCASCADE)",
        lambda s: "%d / %d" % (s["seamless_pass"], s["occt_pass"]))
    add("closed solids in seamless's B-rep: seamless PASS",
        lambda s: "%d of %d" % (s["solids_pass"], s["solids"]))
    add("seamless within D, both ways (measured)",
        lambda s: "%d (%d), worst %s D" % (s["within_D"], s["measured"], num(s["worst_dev"], 3)))
    add("seamless within D or the B-rep's larger gap (measured)",
        lambda s: "%d (%d; %d files with a gap above D)" % (s["within_gap"], s["measured"],
                                                            s["gapped"]))
    add("OpenCASCADE within D, both ways (measured)",
        lambda s: "%d (%d), worst %s D" % (s["occt_within_D"], s["occt_measured"],
                                           num(s["occt_worst_dev"], 3)))
    add("files both meshed", lambda s: str(s["both"]))
    add("triangles, geometric mean of the ratio", lambda s: num(s["geomean"], 4))
    add("... over the B-rep files (trimmed faces) / untrimmed surfaces",
        lambda s: "%s (%d) / %s (%d)" % (num(s["brep_geomean"], 4), len(s["brep_ratios"]),
                                         num(s["surface_geomean"], 4), len(s["surface_ratios"])))
    add("total time 1 thread: seamless / OpenCASCADE",
        lambda s: "%s / %s" % (num(s["t1"][0]), num(s["t1"][1])))
    add("total time 2 threads: seamless / OpenCASCADE",
        lambda s: "%s / %s" % (num(s["t2"][0]), num(s["t2"][1])))
    return lines, sums


def goals(results, sums):
    lines = ["## Goals of issue 28, section 4", ""]
    for lv, s in zip(results["levels"], sums):
        n = s["files"]
        t2 = s["t2"][0] / s["t2"][1] if s["t2"][1] > 0 else None
        lines += [
            "At D = %g x diagonal:" % lv, "",
            "- every corpus file tessellates: %s (%d of %d)" % (
                "met" if s["seamless_ok"] == n else "not met, %d short" % (n - s["seamless_ok"]),
                s["seamless_ok"], n),
            "- every closed solid closed, `check --closed` PASS: %s (%d of the %d files seamless "
            "reads as closed solids pass; %d of its %d meshes have no defect)" % (
                "met" if s["solids_pass"] == s["solids"] and s["seamless_ok"] == n else
                "not met", s["solids_pass"], s["solids"], s["seamless_sound"], s["seamless_ok"]),
            "- measured deviation <= D on every file: %s (%d of the %d files measured are "
            "within D, worst %s D; %d files not measured)" % (
                "met" if s["measured"] == n and s["within_D"] == n else "not met",
                s["within_D"], s["measured"], num(s["worst_dev"]), n - s["measured"]) +
            "; within D or, where larger, the B-rep's own gap (its edge curves measured off "
            "their faces): %d of %d" % (s["within_gap"], s["measured"]),
            "- no more triangles than OpenCASCADE (geometric mean): %s" % (
                "no file meshed by both" if s["geomean"] is None else "%s (%s)" % (
                    "met" if s["geomean"] <= 1 else "not met, %.0f%% more" % (
                        100 * (s["geomean"] - 1)), num(s["geomean"]))) + (
                "; B-rep files (trimmed faces) %s, untrimmed surfaces %s" % (
                    num(s["brep_geomean"]), num(s["surface_geomean"]))
                if s["brep_geomean"] and s["surface_geomean"] else ""),
            "- total time at most half of OpenCASCADE's on 2 threads: %s" % (
                "no file meshed by both" if t2 is None else "%s (%s of it, over %d files)" % (
                    "met" if t2 <= 0.5 else "not met", num(t2), s["both"])),
            ""]
    return lines


def markdown(results):
    m = results["machine"]
    lines = [
        "# CAD parts: seamless against OpenCASCADE's BRepMesh",
        "",
        "Regenerated by one command from the source tree, after building with "
        "`-DSEAMLESS_BUILD_BENCH=ON`:",
        "",
        "    python3 bench/cad/run_cad_bench.py",
        "",
        "(`--help` for its options; meshes and the raw results.json go to build/cad-bench/). "
        "Issue 28, section 4.",
        "",
        "- Machine: %s, %s cores, %s; load average %s at the start, %s at the end; the "
        "run took %.0f minutes." % (m["cpu"], m["cores"], m["system"], " / ".join(m["load"]),
                                    " / ".join(m.get("load_end", [])), m.get("wall_minutes", 0)),
        "- Date %s; seamless %s; OpenCASCADE %s." % (m["date"], m["commit"], m["occt"]),
        "- Files: every STEP/IGES file of ../shared/models/cad-corpus/ and data/models/cad/ "
        "(sub-folders included). D is a fraction of the bounding box diagonal "
        "(OpenCASCADE's BRepBndLib::AddOptimal of the shape read, lengths in the file's "
        "unit as seamless reads them); angle %g rad (seamless: `--angle %.4g` degrees)." % (
            results["angle"], math.degrees(results["angle"])),
        "- seamless: `seamless tessellate FILE -o OUT.ply --tolerance D --angle A --threads 1|2 "
        "--stats`; time: the stats' `seconds` less `brep.bound_seconds` (meshing; reading and the "
        "certified bound excluded: OpenCASCADE computes no bound).",
        "- OpenCASCADE: `occt_mesh` (bench/cad/occt_mesh.cpp): STEPControl_Reader / "
        "IGESControl_Reader, then BRepMesh_IncrementalMesh (Deflection D, Angle A, absolute, "
        "InParallel on 2 threads, TBB capped to the thread count), timed apart from reading. "
        "The mesh is what its users get from StlAPI_Writer or RWGltf_CafWriter: every face's "
        "triangulation with its location, reversed faces flipped, nodes per face (the nodes of "
        "shared edges are not merged; `seamless check` welds bit-identical positions).",
        "- Times: the median of %d meshings (seamless: of up to %d runs); every run limited to "
        "%g s." % (results["repeat"], results["repeat"], results["timeout"]),
        "- check: `seamless check --closed --json` (docs/check.md): PASS, or the defects "
        "counted. Both meshes are PLY with solid ids (occt_mesh: OpenCASCADE's solids as "
        "explored), so each solid is judged apart: solids touching or interpenetrating as "
        "the file has them are contacts, said after the verdict (`3 of 18 solids in "
        "contact`), not defects.",
        "- Deviation: `brep_deviation MODEL MESH` (lib/mesh/deviation/brep_deviation.h), the "
        "same code for both meshes, from positions and triangles alone: face->mesh samples "
        "each face on a (u,v) grid kept inside its loops, plus its edges' curves, against the "
        "mesh; mesh->face projects corners, edge midpoints and centroids of every triangle "
        "onto the trimmed faces (from the nearest face samples, and from the nearest edge "
        "samples onto the faces of their edges; for the points that may hold the maximum, "
        "also from every face and edge with a sample within the distance found plus one "
        "sample spacing, 2e-3 of the diagonal). Both are sampled, lower estimates of the "
        "Hausdorff distance. A model without trimmed faces is measured against its whole "
        "surfaces. Files seamless cannot read have no deviation. Each sample's distance is to "
        "a point found on the faces, so where Newton misses the closest point the mesh->face "
        "figure is too high. "
        "The B-rep's gap is seamless's `--stats` `brep.max_edge_offset`: the largest measured "
        "distance of an edge's curve from its face's surface at the boundary points, which no "
        "mesh of both faces can be nearer than to one of them.",
        "",
    ]
    table, sums = summary_table(results)
    lines += table + [""] + goals(results, sums)
    for lv in results["levels"]:
        lines += level_table(results, lv) + [""]
    return "\n".join(lines)
