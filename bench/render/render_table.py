# SPDX-License-Identifier: MIT
# Writes docs/results/render.md from the runs of bench/render/bench_render.sh.
import glob, json, math, statistics, sys

work, out_md, model, ncpu, date, threads, reps, has_embree = (sys.argv[1:8] + [""])[:8]
scenes = ["teapot", "scene1", "scene2", "scene2a", "scene3"]
main_runs = [("640x480", 16), ("1280x1024", 256)]
scaling = [("320x240", 16), ("640x480", 16), ("1280x1024", 16)]


# Written by hand with the figures of the run that introduced it (2026-12-01,
# second round of issue 10); the tables above are regenerated, this section is not.
ASSESSMENT = """## Issue 10: before and after, and where the goals stand

The run of 2026-12-01 (second round): `THREADS=2 REPS=3 CONFIGS="640x480:16 1280x1024:256"`,
then `THREADS=2 REPS=1 CONFIGS="320x240:16 1280x1024:16"` for the scaling rows (one run each,
for lack of time); the machine's load average was 5.5-10 on its 2 cores during the run (other
helpers compiling), so wall-clock seconds are 2-3 times the CPU seconds; compare the ratios
within the run, and the CPU seconds per step.

**Where the goals stand.** None holds. TRAY/INTRACY at 640x480 x 16 is 0.12 (teapot), 0.26,
0.33, 0.29, 0.18 (scenes 1, 2, 2a, 3) against >= 1; at 1280x1024 x 256 0.08 on the teapot
against >= 2 (scenes: 0.21, 0.26, 0.33, 0.18). The scaling exponent over 320x240-1280x1024 at
16 levels is 0.70-0.82 on wall-clock time and 0.73-0.86 on INTRACY's CPU seconds (sum of the
steps) against <= 0.6. Embree is 4-12 times faster than TRAY and 18-48 times faster than INTRACY.

**First round** (earlier run, same machine, heavier load): ratios 0.07, 0.16, 0.22, 0.18, 0.10
at 640x480 x 16 and 0.07 at 1280x1024 x 256, from 0.03 / 0.10-0.11 / 0.02 on the landed main.

**Second round: counted first.** `perf record` of `seamless render data/scenes/teapot.json
--threads 1 --size 320x240` at the start: 33% `horner_point`, 12% `real_polynomial_range`,
7% `horner1`, 6% `combine`, 4% `horner`, 3% `polynomial_range` (about 65% range enclosures of
power forms), 6% + 3% + 3% the triangle-cluster systems of SHADE's shadow test
(`TriangleSystem`, `gauss_seidel<3>`); 12,664 samples. `--stats` (CPU seconds): single pixels
1.12 s, narrowing 0.76 s, SHADE 0.57 s, certificate 0.06 s; 20.5 range enclosures per pixel.
With call graphs (`--call-graph dwarf`, after the narrow-coefficient change below):
`newton_certified` 34% of the run; after sharing the Jacobians, `mark_jacobian` on halved boxes
still 15%; SHADE's `lights` (shadow clusters) 19% on the teapot and 39% on scene 3, half of it
in `covers_triangle`.

What changed, each measured on the same 1-thread 320x240 render (CPU seconds from `--stats`,
old and new library alternating; range enclosures per pixel are exact counts):
- single pixels: the pixels of a sub-screen of at most 16 pixels share one Jacobian per mark,
  enclosed over the mark's box for all of their rays (a Lipschitz matrix for each ray); Newton
  runs before the miss test (the miss test only where no hit was proved); an undecided box is
  retried on the Hansen-Sengupta step's contraction (Theorem 6 i) instead of on halves of the
  whole box: teapot single pixels 1.30 -> 0.54 s, enclosures per pixel 20.5 -> 15.1,
  Hansen-Sengupta steps 148,716 -> 81,557 (`pixel_solve.cpp`);
- cluster SHADE: at most 4 triangles are tried as the one certain blocker of a light before
  the light is undecided (B split): the later ones never blocked a cluster on the teapot or
  scenes 1 and 3 (the same sub-screens, the same shadowed-cluster counts, the same teapot
  image), and the search was most of SHADE: 0.54 / 0.30 / 1.72 s -> 0.06 / 0.06 / 0.13 s
  (teapot / scene 1 / scene 3) (`cluster_shade.cpp`);
- coefficients as narrow as rounding leaves them (patch power forms, single rays' systems)
  take one real range of the midpoint polynomial widened by their widths instead of Lemma 2's
  two: about 5% (`enclosure.cpp`);
- `cluster_system` writes X - aZ, Y - bZ directly instead of the generic `combine`, and the
  silhouette test reuses the narrowing's last derivative ranges: 15.1 -> 14.5 enclosures per
  pixel, single pixels 0.54 -> 0.49 s.
Tried and dropped: stopping the narrowing passes at 50% instead of 80% shrinkage (3% fewer
enclosures, no measurable time); solving sub-screens of up to 40 pixels pixel by pixel
(`RenderOptions::pixel_subscreen` 40 instead of 16): 640x480 x 16, 1 thread, CPU seconds
teapot 3.47 -> 2.4-2.8, scene 3 6.16 -> 4.0-4.2, range enclosures per pixel 10.0 -> 6.9 and
25.0 -> 13.8 (80: teapot 3.22, scene 3 3.58), but the default scene's single-pixel fraction
becomes 0.69, above the 0.6 that `render: INTRACY agrees with the per-pixel reference on the
default scene` requires (INTRACY must paint most of the screen by clusters); the threshold was
not loosened, so 16 stays. Where clusters cost more than their pixels, the clusters are what
must get cheaper.

After (same command): 7,090 samples (1.8 times fewer): 30% `horner_point`, 11%
`polynomial_range`, 11% `real_polynomial_range`, 6% `primary_rows`, 6% `horner1`, 5%
`horner`; shadow clusters below 1%. Per step: narrowing 0.74 s, single pixels 0.50 s, SHADE
0.06 s, certificate 0.06 s; 14.5 range enclosures per pixel. TRAY on the same render: 0.27 s
user time.

**Why the goals are still far.** INTRACY's cost is now mostly step 3's narrowing (55-70% of the
CPU seconds at 640x480 x 16): about 38 range enclosures of 0.5-1 us per marked patch and
sub-screen (1.8 passes of Theorem 10 at 12 ranges each, 12 for the mean-value hull, 4 for the
silhouette Jacobian before this round), and 2-4 marks per sub-screen. The single-pixel fraction
stays 0.24-0.61 at 640x480 (0.16-0.80 at 1280x1024 x 256) because a cluster needs a proof that
one patch covers it, so every patch seam, silhouette and shadow edge splits down to pixels;
TRAY's whole pixel is a few ray-triangle tests. The exponent is above 0.6 for the same reason:
the seams' pixels grow linearly with the resolution. What is left, in the order the profile
suggests: Bernstein-form ranges in camera space (G = X - aZ linear in a, b: the hull of the
subpatch's coefficients, de Casteljau from the parent's, carried by the mark, instead of
re-narrowing from the parent's box with Lemma 2 on the power form); clusters across the seams
of one surface (one G over the union of its patches); a predicting pass (coarse item buffer of
patch ids) so that certificates are tried only where one patch covers B; for 256 levels the
second-order intensity criterion of the issue.
"""


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
L.append(f"- Date: {date}; `--threads {threads}`, median of {reps}\n")
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
L.append("Thread CPU seconds per step (summed over threads): step 3's narrowing (Theorem 10, "
         "covering bisection, silhouette separation), step 7's certificate (Hansen-Sengupta "
         "over the cluster), step 8's SHADE (enclosures, shadow clusters, corner rays; without "
         "secondary clusters), SHADE steps 3-4's secondary clusters, step 6's single pixels; "
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
