# SPDX-License-Identifier: MIT
# Writes docs/results/render.md from the runs of bench/render/bench_render.sh.
import glob, json, math, os, statistics, sys

work, out_md, model, ncpu, date, threads, reps, has_embree = (sys.argv[1:8] + [""])[:8]
scenes = ["teapot", "scene1", "scene2", "scene2a", "scene3"]
main_runs = [("640x480", 16), ("1280x1024", 256)]
scaling = [("320x240", 16), ("640x480", 16), ("1280x1024", 16)]


# Written by hand with the figures of the runs it describes (issue 10); the
# tables are regenerated, this section is not: bench/render/render_assessment.md.
with open(os.path.join(os.path.dirname(os.path.abspath(__file__)), "render_assessment.md")) as fh:
    ASSESSMENT = fh.read()


def runs(sc, method, size, levels):
    out = []
    for f in sorted(glob.glob(f"{work}/{sc}-{method}-{size}-{levels}-*.json")):
        with open(f) as fh:
            out.append(json.load(fh))
    return out


def median_run(sc, method, size, levels):
    rs = runs(sc, method, size, levels)
    if not rs:
        return None
    rs.sort(key=lambda r: r["seconds"])
    return rs[len(rs) // 2]


def secs(r):
    return r["seconds"] if r else float("nan")


L = ["# Rendering: INTRACY against TRAY and Embree (paper section 8, Table 2; issue 10)\n"]
L.append("Regenerate with `bench/render/bench_render.sh` (Release build in `build/`; "
         "`REPS=3 THREADS=2` by default). Scenes from `data/scenes/` (teapot: teapot and "
         "ground, one light; scenes 1, 2, 2a, 3: the paper's, with shadows, mirror and "
         "glass), RGB, dither on. For every scene and size INTRACY, TRAY and Embree run "
         "one after the other; each time is the median of the runs.\n")
L.append(f"- Machine: {model}, nproc {ncpu}, shared with other jobs (wall-clock times are noisy; "
         "compare the ratios within one run)")
def reps_of(size, levels):
    n = {len(glob.glob(f"{work}/{sc}-intracy-{size}-{levels}-*.json")) for sc in scenes}
    return "/".join(str(k) for k in sorted(n))


main_reps = ", ".join(f"{reps_of(sz, lv)} at {sz} x {lv}" for sz, lv in main_runs)
L.append(f"- Date: {date}; `--threads {threads}`; runs per median: {main_reps}, "
         f"{reps_of('320x240', 16)} for the scaling rows\n")
L.append("Times are wall-clock seconds including the precalculation (INTRACY: projection of "
         "the patches and, with shadows or secondary rays, the tessellation; TRAY and Embree: "
         "the tessellation, Embree also its BVH). Ratio = TRAY / INTRACY (> 1: INTRACY faster; "
         "the paper: 2.5-3.1 at 640x480 x 16, about 3.1 expected at 1280x1024 x 256). "
         "Embree (`bench_render_embree`) traces the same triangles, one primary ray per pixel "
         "and shadow rays, with the same shading, but no reflected or refracted rays (on the "
         "teapot scene its image equals TRAY's pixel for pixel; on scenes 1-3 the mirror and "
         "glass differ).\n")
L.append("| scene | size x levels | INTRACY s | TRAY s | Embree s | TRAY/INTRACY | Embree/INTRACY |")
L.append("|---|---|---|---|---|---|---|")
for sc in scenes:
    for size, lv in main_runs:
        i, t, e = (median_run(sc, m, size, lv) for m in ("intracy", "tray", "embree"))
        if not i or not t:
            continue
        es = f"{secs(e):.2f}" if e else "-"
        er = f"{secs(e) / secs(i):.2f}" if e else "-"
        L.append(f"| {sc} | {size} x {lv} | {secs(i):.2f} | {secs(t):.2f} | {es} | "
                 f"**{secs(t) / secs(i):.2f}** | {er} |")
L.append("")
L.append("## Scaling with the pixel count (16 levels)\n")
L.append("Exponent k of time ~ pixels^k, least squares over 320x240, 640x480, 1280x1024 "
         "(the goal: INTRACY k <= 0.6; TRAY's is about 1).\n")
L.append("| scene | INTRACY s (320x240 / 640x480 / 1280x1024) | k INTRACY | TRAY s | k TRAY |")
L.append("|---|---|---|---|---|")


def exponent(ts):
    xs = [math.log(int(s.split("x")[0]) * int(s.split("x")[1])) for s, _ in scaling]
    ys = [math.log(t) for t in ts]
    mx, my = sum(xs) / len(xs), sum(ys) / len(ys)
    return sum((x - mx) * (y - my) for x, y in zip(xs, ys)) / sum((x - mx) ** 2 for x in xs)


for sc in scenes:
    cells = []
    for m in ("intracy", "tray"):
        rs = [median_run(sc, m, s, lv) for s, lv in scaling]
        if any(r is None for r in rs):
            cells += ["-", "-"]
            continue
        ts = [secs(r) for r in rs]
        cells += [" / ".join(f"{t:.2f}" for t in ts), f"{exponent(ts):.2f}"]
    L.append(f"| {sc} | " + " | ".join(cells) + " |")
L.append("")
L.append("## Where INTRACY's time goes\n")
L.append("CPU seconds per step (summed over threads; each step's monotonic-clock seconds "
         "scaled by its screen part's thread CPU / wall ratio, step_clock.h): step 3's "
         "narrowing (Bezier clipping of the marks' subpatches, covering bisection, silhouette "
         "separation), step 7's certificate (Hansen-Sengupta "
         "over the cluster), step 8's SHADE (enclosures, shadow clusters, corner rays; without "
         "secondary clusters), SHADE steps 3-4's secondary clusters, step 6's single pixels "
         "(sub-screens of at most 16 pixels solved pixel by pixel included); "
         "range enclosures (power-form Horner ranges) per pixel; single pixels solved by "
         "certified Newton / all pixel x patch solves.\n")
L.append("| scene | size x levels | narrowing | certificate | SHADE | secondary | single pixels "
         "| enclosures/pixel | HS steps | single-pixel fraction | Newton-decided boxes / pixel x patch solves |")
L.append("|---|---|---|---|---|---|---|---|---|---|---|")
for sc in scenes:
    for size, lv in main_runs:
        i = median_run(sc, "intracy", size, lv)
        if not i or "step_seconds" not in i:
            continue
        s = i["step_seconds"]
        L.append(f"| {sc} | {size} x {lv} | {s['narrowing']:.2f} | {s['certificate']:.2f} | "
                 f"{s['shade']:.2f} | {s['secondary_clusters']:.2f} | {s['single_pixels']:.2f} | "
                 f"{i['enclosures_per_pixel']:.1f} | {i['hs_steps']} | "
                 f"{i['single_pixel_fraction']:.3f} | "
                 f"{i['pixel_newton_certified']} / {i['pixel_patch_solves']} |")
L.append("")
L.append("## Sizes of equally coloured sub-screens (cf. the paper's Table 3)\n")
L.append("Sub-screens painted at once, bucketed by pixel count (Nops): count / share of the "
         "screen in %.\n")


def buckets(maxsize):
    out = [(str(k), k, k) for k in (1, 2, 3, 4)]
    lo = 5
    while lo <= maxsize:
        hi = 8 if lo == 5 else 2 * lo - 2
        out.append((f"{lo}-{hi}", lo, hi))
        lo = hi + 1
    return out


cols = [(sc, size, lv) for sc in scenes for size, lv in main_runs]
stats = {c: median_run(c[0], "intracy", c[1], c[2]) for c in cols}
cols = [c for c in cols if stats[c]]
maxsize = max([int(k) for c in cols for k in stats[c]["subscreens_by_size"]] + [1])
L.append("| Nops | " + " | ".join(f"{sc} {size}x{lv}" for sc, size, lv in cols) + " |")
L.append("|---|" + "---|" * len(cols))
for label, lo, hi in buckets(maxsize):
    cells = []
    for c in cols:
        h = stats[c]["subscreens_by_size"]
        w, hh = map(int, c[1].split("x"))
        n = sum(v for k, v in h.items() if lo <= int(k) <= hi)
        px = sum(int(k) * v for k, v in h.items() if lo <= int(k) <= hi)
        cells.append(f"{n} / {100.0 * px / (w * hh):.1f}")
    L.append(f"| {label} | " + " | ".join(cells) + " |")
L.append("")
L.append(ASSESSMENT)
for sc in scenes[1:]:
    L.append(f"![{sc} INTRACY](images/{sc}-intracy.png) ![{sc} TRAY](images/{sc}-tray.png)\n")
with open(out_md, "w") as f:
    f.write("\n".join(L) + "\n")
print(f"bench_render: wrote {out_md}", file=sys.stderr)
