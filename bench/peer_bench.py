#!/usr/bin/env python3
"""Peer benchmark: cutcom's fast engine against LinuxCNC's standalone interpreter `rs274`.

Writes the same contour in the SINUMERIK dialect (for cutcom) and the LinuxCNC dialect (for
`rs274 -g`, cutter compensation G42.1 with the tool diameter), checks that the two tool paths
agree, times both whole processes in the same run (median of --runs runs, interleaved), and
writes docs/performance.md with the table and a bar chart (docs/performance-peer.svg).

The contours are chosen where the two controls' rules coincide: the approach is collinear with
the first element (SINUMERIK NORM, LinuxCNC's entry move), corners are G450 transition circles
at every convex corner (MD20230 CUTCOM_CURVE_INSERT_LIMIT = 0) and intersections at concave ones.

    python3 bench/peer_bench.py [--blocks 200000] [--runs 5] [--cutcom build/cli/cutcom]
                                [--rs274 rs274] [--write-docs]

Without `rs274` (Debian package linuxcnc-uspace) only cutcom is timed. Needs nothing beyond the
Python standard library.
"""

import argparse
import json
import math
import os
import re
import shutil
import statistics
import subprocess
import sys
import tempfile
import time

RADIUS = 0.5  # tool radius, mm (LinuxCNC: D = diameter)


# --- contours -------------------------------------------------------------------------------
# A contour is a list of moves in the plane: ("line", x, y) or ("arc", x, y, i, j, ccw) with
# the centre relative to the start. Both dialects are written from it.


def bumps_and_corners(n):
    """A closed counter-clockwise loop: its bottom edge made of n-3 pieces (lines, outward
    half-circle bumps, shallow inward dents, small corners), then back along three lines. With
    the tool on the right (G42) the tool runs outside."""
    moves, x = [], 0.0
    units = max(1, (n - 3) // 6)
    for k in range(units):
        moves.append(("line", x + 2, 0.0))  # straight
        # bump: half circle below the edge (outward), radius 1
        moves.append(("arc", x + 4, 0.0, 1.0, 0.0, True))
        moves.append(("line", x + 6, 0.0))
        # dent: a shallow arc above the edge (inward, centre below), radius 4 on a chord of 2
        h = math.sqrt(16 - 1)
        moves.append(("arc", x + 8, 0.0, 1.0, -h, False))
        # small corner: down by 0.1 and back to the edge
        moves.append(("line", x + 9, -0.1 if k % 2 == 0 else 0.1))
        x += 9
        moves.append(("line", x + 1, 0.0))
        x += 1
    height = 40.0
    moves += [("line", x, height), ("line", 0.0, height), ("line", 0.0, 0.0)]
    return moves


def tiny_segments(n):
    """A CAM-like closed loop: a 30-sided polygon (turning 12 degrees at each vertex) written as
    n pieces: each side a run of collinear 0.02 mm segments, each vertex cut by a small arc
    (radius about 0.56 mm) that leaves a corner of about 4 degrees at either end. Coordinates
    are whole multiples of 0.0001 mm, so runs are exactly collinear and the arcs' centres lie
    exactly on their chords' bisectors. Every corner is convex for the tool outside and at
    least 3 degrees, where the two controls' rules coincide (LinuxCNC joins corners under
    0.05 rad without a circle)."""
    sides = 30
    run = max(1, n // sides - 1)
    # directions in units of 0.0001 mm, even, symmetric (d[i + 15] = -d[i]): the loop closes
    d = []
    for i in range(sides):
        t = 2 * math.pi * i / sides
        d.append((2 * round(100 * math.cos(t)), 2 * round(100 * math.sin(t))))
    for i in range(sides // 2):
        d[i + sides // 2] = (-d[i][0], -d[i][1])
    moves, x, y = [], 0, 0
    for i in range(sides):
        if i > 0:  # the vertex: an arc over the chord d[i-1] + d[i], centre 14 chords to its left
            cx, cy = d[i - 1][0] + d[i][0], d[i - 1][1] + d[i][1]
            ox, oy = cx // 2 - 14 * cy, cy // 2 + 14 * cx
            moves.append(("arc", (x + cx) / 1e4, (y + cy) / 1e4, ox / 1e4, oy / 1e4, True))
            x, y = x + cx, y + cy
        for _ in range(run):
            x, y = x + d[i][0], y + d[i][1]
            moves.append(("line", x / 1e4, y / 1e4))
    # the last vertex: back into the first side's direction, and the first side's start
    cx, cy = d[-1][0] + d[0][0], d[-1][1] + d[0][1]
    ox, oy = cx // 2 - 14 * cy, cy // 2 + 14 * cx
    moves.append(("arc", (x + cx) / 1e4, (y + cy) / 1e4, ox / 1e4, oy / 1e4, True))
    return moves  # back at the start: the sides and the arcs each sum to zero


KINDS = {"lines+arcs": bumps_and_corners, "tiny segments": tiny_segments}


def fmt(v):
    s = f"{v:.4f}".rstrip("0").rstrip(".")
    return "0" if s in ("-0", "") else s


def approach_start(moves):
    """Where the approach starts: on the backward extension of the first piece (a line from the
    origin), ten times its length away, so the approach is collinear with it exactly."""
    x, y = moves[0][1], moves[0][2]
    k = round(10 / math.hypot(x, y))  # about 10 mm, an exact multiple of the first piece
    return fmt(-k * x), fmt(-k * y)


def sinumerik_program(moves, cdon=False):
    sx, sy = approach_start(moves)
    out = [
        "; peer benchmark contour (bench/peer_bench.py)",
        "$TC_DP1[1,1]=120",
        f"$TC_DP6[1,1]={fmt(RADIUS)}",
        "N1 G17 G90 G71 G450 T1 D1 F1000" + (" CDON" if cdon else ""),
        f"G0 X{sx} Y{sy}",
        "G42 G1 X0 Y0",
        *contour_blocks(moves),
        "G40 G1 X-10 Y-5",
        "M30",
    ]
    return "\n".join(out) + "\n"


def contour_blocks(moves):
    """The contour's blocks, the same words in both dialects (G1, G2/G3 with I J)."""
    for m in moves:
        if m[0] == "line":
            yield f"G1 X{fmt(m[1])} Y{fmt(m[2])}"
        else:
            yield f"{'G3' if m[5] else 'G2'} X{fmt(m[1])} Y{fmt(m[2])} I{fmt(m[3])} J{fmt(m[4])}"


def linuxcnc_program(moves):
    sx, sy = approach_start(moves)
    out = ["G21 G17 G90 G64 F1000", f"G0 X{sx} Y{sy}", f"G42.1 D{fmt(2 * RADIUS)} G1 X0 Y0", *contour_blocks(moves),
           "G40 G1 X-10 Y-5", "M2"]
    return "\n".join(out) + "\n"


# --- paths ----------------------------------------------------------------------------------

CANON = re.compile(r"(STRAIGHT_TRAVERSE|STRAIGHT_FEED|ARC_FEED)\(([^)]*)\)")


def rs274_path(text):
    """(kind, end x, end y, centre x, centre y) of each move rs274 prints."""
    path = []
    for m in CANON.finditer(text):
        v = [float(a) for a in m.group(2).split(",")[:6]]
        if m.group(1) == "ARC_FEED":
            path.append(("arc+" if v[4] > 0 else "arc-", v[0], v[1], v[2], v[3]))
        else:
            path.append(("rapid" if m.group(1) == "STRAIGHT_TRAVERSE" else "line", v[0], v[1], None, None))
    return path


def cutcom_path(doc):
    path = []
    for e in doc["path"]:
        if e.get("rapid"):
            path.append(("rapid", e["end"][0], e["end"][1], None, None))
        elif e["type"] == "arc":
            path.append(("arc+" if e["ccw"] else "arc-", e["end"][0], e["end"][1], e["center"][0], e["center"][1]))
        else:
            path.append(("line", e["end"][0], e["end"][1], None, None))
    return path


def compare(a, b, tol=2e-4):
    """First difference of two paths (rs274 prints 4 places), or None."""
    if len(a) != len(b):
        return f"{len(a)} moves against {len(b)}"
    for k, (p, q) in enumerate(zip(a, b)):
        if p[0] != q[0]:
            return f"move {k}: {p[0]} against {q[0]}"
        for u, v in zip(p[1:], q[1:]):
            if (u is None) != (v is None) or (u is not None and abs(u - v) > tol):
                return f"move {k}: {p} against {q}"
    return None


# --- timing ---------------------------------------------------------------------------------


def quartiles(values):
    """First and third quartile (the median of each half's values)."""
    if len(values) < 4:
        return (min(values), max(values))
    q = statistics.quantiles(values, n=4)
    return (q[0], q[2])


def timed(cmd):
    t = time.perf_counter()
    subprocess.run(cmd, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, check=True)
    return time.perf_counter() - t


def stage_times(cmd, runs):
    """Medians over `runs` runs of each thread's processor time and of the elapsed time
    (`cutcom run --stage-times`, on standard error): which thread sets the pace."""
    seen = {}
    for _ in range(runs):
        err = subprocess.run([*cmd, "--stage-times"], stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True,
                             check=True).stderr
        for name, seconds in re.findall(r"(reader\+engine|writer|elapsed) (\d+\.\d+) s", err):
            seen.setdefault(name, []).append(float(seconds))
    return {name: statistics.median(v) for name, v in seen.items()}


def peak_kb(cmd):
    """Peak resident memory of a whole process (kB) by GNU time (Debian package `time`); None
    without it. (This script's own memory would count in a child it forks itself.)"""
    gnu_time = shutil.which("time") or ("/usr/bin/time" if os.access("/usr/bin/time", os.X_OK) else None)
    if not gnu_time:
        return None
    r = subprocess.run([gnu_time, "-f", "%M", *cmd], stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
    if r.returncode != 0:
        raise RuntimeError(f"{cmd[0]} failed: {r.stderr[-300:]}")
    return int(r.stderr.strip().splitlines()[-1])


def svg_chart(rows, path):
    """Horizontal bars: seconds per contour and program, cutcom and rs274 side by side."""
    width, bar, gap, left = 720, 18, 14, 230
    scale_max = max([r["cutcom"] for r in rows] + [r["rs274"] or 0 for r in rows]) or 1
    y, parts = 40, []
    for r in rows:
        for who, colour in (("cutcom", "#1f77b4"), ("rs274", "#d62728")):
            v = r[who]
            if v is None:
                continue
            w = (width - left - 90) * v / scale_max
            parts.append(f'<text x="{left - 8}" y="{y + 13}" text-anchor="end">{r["label"]}: {who}</text>')
            parts.append(f'<rect x="{left}" y="{y}" width="{w:.1f}" height="{bar}" fill="{colour}"/>')
            parts.append(f'<text x="{left + w + 6:.1f}" y="{y + 13}">{v:.3f} s</text>')
            y += bar + 4
        y += gap
    height = y + 20
    return (
        f'<svg xmlns="http://www.w3.org/2000/svg" width="{width}" height="{height}" '
        f'font-family="sans-serif" font-size="12">\n'
        f'<text x="10" y="20" font-size="14">Whole process, median seconds (shorter is better)</text>\n'
        + "\n".join(parts)
        + "\n</svg>\n"
    )


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--blocks", type=int, default=200000)
    ap.add_argument("--runs", type=int, default=21)
    ap.add_argument("--cutcom", default="build/cli/cutcom")
    ap.add_argument("--rs274", default="rs274")
    ap.add_argument("--memory-blocks", default="10000,200000,2000000,10000000",
                    help="program lengths at which cutcom's peak memory is measured (flat: the same at all)")
    ap.add_argument("--ref-memory-blocks", default="10000,100000",
                    help="program lengths at which ref's peak memory and time are measured with CDON "
                         "(about 0.25 ms a block)")
    ap.add_argument("--ref-cdof-blocks", default="10000,100000,1000000",
                    help="the same without CDON, the issue's typical contour (about 0.05 ms a block)")
    ap.add_argument("--bench-engines", default="build/bench/bench_engines")
    ap.add_argument("--block-instructions", default="build/bench/block_instructions")
    ap.add_argument("--instruction-blocks", type=int, default=20000,
                    help="program length at which instructions per block are counted under valgrind "
                         "(0: not counted)")
    ap.add_argument("--write-docs", action="store_true", help="write docs/performance.md and its chart")
    a = ap.parse_args()
    rs274 = shutil.which(a.rs274)
    if not os.access(a.cutcom, os.X_OK):
        sys.exit(f"peer_bench: {a.cutcom} is not an executable (build first: bash scripts/setup.sh)")
    tmp = tempfile.mkdtemp(prefix="cutcom-peer-")
    rows, ok = [], True
    md = ["--md", "MD20230=0"]
    for kind, make in KINDS.items():
        moves = make(a.blocks)
        for cdon in (False, True):
            label = f"{kind}{', CDON' if cdon else ''}"
            spf = os.path.join(tmp, f"{kind.replace(' ', '_')}{'_cdon' if cdon else ''}.mpf")
            ngc = os.path.join(tmp, f"{kind.replace(' ', '_')}.ngc")
            with open(spf, "w") as f:
                f.write(sinumerik_program(moves, cdon))
            with open(ngc, "w") as f:
                f.write(linuxcnc_program(moves))
            blocks = sum(1 for _ in open(spf))
            text_cmd = [a.cutcom, "run", spf, *md, "-o", "/dev/null"]
            json_cmd = [a.cutcom, "run", spf, *md, "--format", "json", "-o", "/dev/null"]
            peer_cmd = [rs274, "-g", ngc] if rs274 else None
            agree = "not checked"
            if peer_cmd:
                mine = json.loads(subprocess.run([a.cutcom, "run", spf, *md, "--format", "json"],
                                                 capture_output=True, text=True, check=True).stdout)
                theirs = subprocess.run(peer_cmd, capture_output=True, text=True).stdout
                diff = compare(cutcom_path(mine), rs274_path(theirs))
                agree = "yes" if diff is None else f"NO: {diff}"
                ok &= diff is None
            t_text, t_json, t_peer = [], [], []
            for _ in range(a.runs):  # interleaved: both see the same machine state
                t_text.append(timed(text_cmd))
                t_json.append(timed(json_cmd))
                if peer_cmd:
                    t_peer.append(timed(peer_cmd))
            row = {
                "label": label,
                "blocks": blocks,
                "cutcom": statistics.median(t_text),
                "json": statistics.median(t_json),
                "rs274": statistics.median(t_peer) if t_peer else None,
                # run by run: a pair is timed back to back, so the machine's drift cancels out
                "ratio": statistics.median(p / t for p, t in zip(t_peer, t_text)) if t_peer else None,
                "ratio_json": statistics.median(p / t for p, t in zip(t_peer, t_json)) if t_peer else None,
                # the middle half of the run-by-run ratios: how much the shared machine moved them
                "ratio_quartiles": quartiles([p / t for p, t in zip(t_peer, t_text)]) if t_peer else None,
                "peak_kb": peak_kb(text_cmd),
                "agree": agree,
                "stages": stage_times(text_cmd, a.runs),
                "stages_json": stage_times(json_cmd, a.runs),
            }
            rows.append(row)
            ratio = (f"{row['ratio']:.1f}x (middle half {row['ratio_quartiles'][0]:.1f}–{row['ratio_quartiles'][1]:.1f}; "
                     f"JSON {row['ratio_json']:.1f}x)" if row["rs274"] else "-")
            print(f"{label:26} {blocks:>8} blocks  cutcom {row['cutcom']:.3f} s (json {row['json']:.3f} s, "
                  f"{mb(row['peak_kb'])})  rs274 {row['rs274'] or 0:.3f} s  {ratio}  paths agree: {agree}")
            print(f"{'':26} processor time by thread (text): " +
                  ", ".join(f"{k} {v:.3f} s" for k, v in row["stages"].items()))
    memory = []
    for n in [int(v) for v in a.memory_blocks.split(",") if v]:
        spf = os.path.join(tmp, f"memory_{n}.mpf")
        with open(spf, "w") as f:
            f.write(sinumerik_program(bumps_and_corners(n), cdon=True))
        kb = peak_kb([a.cutcom, "run", spf, *md, "-o", "/dev/null"])
        t = time.perf_counter()
        svg_kb = peak_kb([a.cutcom, "run", spf, *md, "--format", "svg", "-o", "/dev/null"])
        svg_s = time.perf_counter() - t
        # JSON with every decision traced: the lists after the path spill to a temporary file.
        json_kb = peak_kb([a.cutcom, "run", spf, *md, "--format", "json", "--trace", "-o", "/dev/null"])
        memory.append((n, kb, json_kb, svg_kb, svg_s))
        print(f"peak memory, lines+arcs with CDON, {n} blocks: text {mb(kb)}, JSON with trace {mb(json_kb)}, "
              f"SVG {mb(svg_kb)} ({svg_s:.2f} s)")
        os.remove(spf)
    ref_memory = []
    for cdon, lengths in ((False, a.ref_cdof_blocks), (True, a.ref_memory_blocks)):
        label = "lines+arcs" + (", CDON" if cdon else "")
        for n in [int(v) for v in lengths.split(",") if v]:
            spf = os.path.join(tmp, f"ref_memory_{n}.mpf")
            with open(spf, "w") as f:
                f.write(sinumerik_program(bumps_and_corners(n), cdon=cdon))
            t = time.perf_counter()
            kb = peak_kb([a.cutcom, "run", "--engine", "ref", spf, *md, "-o", "/dev/null"])
            ref_memory.append((label, n, kb, time.perf_counter() - t))
            print(f"ref, {label}, {n} blocks: peak memory {mb(kb)}, {ref_memory[-1][3]:.1f} s")
            os.remove(spf)
    start = start_seconds(a, tmp)
    print(f"one block (the process's start and end): {start * 1000:.1f} ms")
    pocket = parametric_rows(a, tmp)
    engines = engine_rows(a)
    for name, median, best in engines:
        print(f"{name:40} median {median / 1e6:.2f} M blocks/s, best {best / 1e6:.2f}")
    instructions = instruction_rows(a, tmp)
    if a.write_docs:
        write_docs(rows, memory, ref_memory, pocket, engines, instructions, start, a)
    shutil.rmtree(tmp, ignore_errors=True)
    sys.exit(0 if ok else 1)


def while_pocket(passes, loop):
    """The pocket of issue "Parametric programs", item 9: passes of four blocks under G41, as a
    WHILE loop computing its coordinates, or the same blocks written out."""
    head = "$TC_DP1[1,1]=120\n$TC_DP6[1,1]=0.2\nN10 G0 X-10 Y0 T1 D1\nN20 G1 G41 X0 Y0 F1000\n"
    if loop:
        body = (f"WHILE KK<{passes}\n  XX=KK*2\n  G1 Y50\n  X=XX+1\n  Y0\n  X=XX+2\n  KK=KK+1\nENDWHILE\n")
        return "DEF INT KK=0\nDEF REAL XX\n" + head + body + "G40 G1 X=XX+20 Y-10\nM30\n"
    body = "".join(f"G1 Y50\nX{2 * k + 1}\nY0\nX{2 * k + 2}\n" for k in range(passes))
    return head + body + f"G40 G1 X{2 * (passes - 1) + 20} Y-10\nM30\n"


def start_seconds(a, tmp):
    """Whole-process time of a program of one block: the process's start, its threads and its
    end, which every cutcom time above includes."""
    path = os.path.join(tmp, "one_block.mpf")
    with open(path, "w") as f:
        f.write("N10 G0 X0 Y0\nM30\n")
    return statistics.median(timed([a.cutcom, "run", path, "-o", "/dev/null"]) for _ in range(a.runs))


def parametric_rows(a, tmp):
    rows = []
    passes = 25000  # 100,000 blocks
    for loop in (True, False):
        path = os.path.join(tmp, f"pocket_{'while' if loop else 'plain'}.mpf")
        with open(path, "w") as f:
            f.write(while_pocket(passes, loop))
        cmd = [a.cutcom, "run", path, "-o", "/dev/null"]
        t = statistics.median(timed(cmd) for _ in range(a.runs))
        rows.append(("WHILE loop" if loop else "written out", 4 * passes + 3, t))
        print(f"pocket, {rows[-1][0]:12} {4 * passes + 3} blocks  {t:.3f} s  {(4 * passes + 3) / t / 1e6:.2f} M blocks/s")
    return rows


def engine_rows(a):
    """The in-process benchmarks (reader + engine, no output) of bench_engines, if built."""
    if not os.access(a.bench_engines, os.X_OK):
        return []
    out = subprocess.run([a.bench_engines, "--benchmark_filter=FastPocket|ReaderLongProgram|FastLongProgram/.*/100000$",
                          f"--benchmark_repetitions={a.runs}", "--benchmark_format=json"],
                         capture_output=True, text=True, check=True).stdout
    runs = {}
    for b in json.loads(out)["benchmarks"]:
        if b.get("run_type") == "iteration":
            runs.setdefault(b["run_name"], []).append(b["items_per_second"])
    return [(name, statistics.median(v), max(v)) for name, v in runs.items()]


def instructions_of(cmd):
    """Instructions the process executed, counted by valgrind (callgrind's total)."""
    out = subprocess.run(["valgrind", "--tool=callgrind", "--callgrind-out-file=/dev/null", *cmd],
                         capture_output=True, text=True)
    if out.returncode != 0:
        sys.exit(f"peer_bench: {' '.join(cmd)} failed under valgrind:\n{out.stderr[-2000:]}")
    m = re.search(r"Collected : (\d+)", out.stderr)
    if not m:
        sys.exit(f"peer_bench: no instruction count from valgrind for {' '.join(cmd)}")
    return int(m.group(1))


def instruction_rows(a, tmp):
    """Instructions per block of the reader alone and of the reader with the fast engine, on the
    peer contours (bench/block_instructions under valgrind): a figure that a shared machine's load
    does not move, to measure small changes by. The cost of starting the process is taken out by
    counting an empty program too."""
    if a.instruction_blocks <= 0 or not shutil.which("valgrind") or not os.access(a.block_instructions, os.X_OK):
        return []
    empty = os.path.join(tmp, "empty.mpf")
    with open(empty, "w") as f:
        f.write("M30\n")
    modes = ((), ("--reader",), ("--text",), ("--json",))
    base = {mode: instructions_of([a.block_instructions, empty, *mode]) for mode in modes}
    rows = []
    for kind, make in KINDS.items():
        moves = make(a.instruction_blocks)
        for cdon in (False, True):
            path = os.path.join(tmp, f"instructions_{kind.replace(' ', '_')}{'_cdon' if cdon else ''}.mpf")
            with open(path, "w") as f:
                f.write(sinumerik_program(moves, cdon))
            blocks = sum(1 for _ in open(path))
            per_block = {mode: (instructions_of([a.block_instructions, path, *mode]) - base[mode]) / blocks
                         for mode in modes}
            reader, total = per_block[("--reader",)], per_block[()]
            text, js = per_block[("--text",)] - total, per_block[("--json",)] - total
            rows.append((f"{kind}{', CDON' if cdon else ''}", blocks, reader, total - reader, total, text, js))
            print(f"instructions per block, {rows[-1][0]:22} reader {reader:.0f}, fast {total - reader:.0f}, "
                  f"together {total:.0f}, text writer {text:.0f}, JSON writer {js:.0f}")
    return rows


def mb(kb):
    return f"{kb / 1024:.1f} MB" if kb else "not measured"


def build_kind(cutcom):
    """How the measured cutcom was built, from its build directory's CMake cache."""
    cache = os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(cutcom))), "CMakeCache.txt")
    pgo = "unknown"
    try:
        pgo = next(l.split("=", 1)[1].strip() for l in open(cache) if l.startswith("CUTCOM_PGO:"))
    except (OSError, StopIteration):
        pass
    if pgo == "use":
        return ("built as `scripts/setup.sh` builds it: Release, profile-guided (trained by "
                "`scripts/pgo_training.sh` on its own serpentine passes, not on these contours) and "
                "link-time optimized")
    return f"built with CUTCOM_PGO={pgo} (not profile-guided)"


def write_docs(rows, memory, ref_memory, pocket, engines, instructions, start, a):
    here = os.path.dirname(os.path.abspath(__file__))
    docs = os.path.join(here, "..", "docs")
    with open(os.path.join(docs, "performance-peer.svg"), "w") as f:
        f.write(svg_chart(rows, None))
    cpu = "unknown"
    try:
        cpu = next(l.split(":", 1)[1].strip() for l in open("/proc/cpuinfo") if l.startswith("model name"))
    except (OSError, StopIteration):
        pass
    lines = [
        "# Performance",
        "",
        "Written by `python3 bench/peer_bench.py --write-docs` (do not edit by hand). Whole processes,",
        f"median of {a.runs} runs each, interleaved, output to `/dev/null`; machine: {cpu}, "
        f"{os.cpu_count()} cores. The ratios are the median of the run-by-run ratios (rs274 and cutcom",
        "run back to back), which the machine's drift moves less than a ratio of medians; beside the",
        "text ratio, the middle half of the run-by-run ratios (this machine is shared: its speed moves).",
        "cutcom reads and compensates on one thread and writes on a second: a block (2.7 KB) stays on",
        "the core that read it, and only the path's elements cross to the writer's (a reader on a third",
        "thread of its own cost more in blocks crossing between the cores than it saved: 20 to 27 % of",
        "the whole process's time on these contours).",
        "cutcom: `cutcom run FILE --md MD20230=0` (fast engine, text; JSON in its own column), "
        f"{build_kind(a.cutcom)}.",
        "LinuxCNC: `rs274 -g FILE` (standalone interpreter, cutter compensation `G42.1 D<diameter>`).",
        "The two tool paths are compared move by move (kind, end point and centre to 2e-4 mm, rs274",
        "prints four places) before timing; the contours are those where the two controls' rules",
        "coincide (approach collinear with the first element, G450 circles at every convex corner).",
        "",
        "| contour | blocks | cutcom text (s) | cutcom JSON (s) | rs274 (s) | rs274 / cutcom text | rs274 / cutcom JSON "
        "| cutcom peak memory | paths agree |",
        "|---|---|---|---|---|---|---|---|---|",
    ]
    for r in rows:
        ratio = (f"{r['ratio']:.1f}x ({r['ratio_quartiles'][0]:.1f}–{r['ratio_quartiles'][1]:.1f})"
                 if r["rs274"] else "-")
        ratio_json = f"{r['ratio_json']:.1f}x" if r["rs274"] else "-"
        peer = f"{r['rs274']:.3f}" if r["rs274"] else "not installed"
        lines.append(f"| {r['label']} | {r['blocks']} | {r['cutcom']:.3f} | {r['json']:.3f} | {peer} | {ratio} | "
                     f"{ratio_json} | {mb(r['peak_kb'])} | {r['agree']} |")
    lines += ["", f"A program of one block takes {start * 1000:.1f} ms: the process's start (the dynamic loader, "
              "the allocator), its writer's thread and its end, in every cutcom time above. cutcom is linked "
              "with mimalloc: tcmalloc, with which ref runs as fast, zeroed a 2 MB page map at every start, "
              "3 ms more."]
    lines += ["", "![whole-process times](performance-peer.svg)", "",
              "## Where the time goes", "",
              "The processor time of each thread (`cutcom run --stage-times`, medians of "
              f"{a.runs} runs; text, then JSON): the reader and the engine on one, the writer on the other. "
              "The two overlap: a run lasts about as long as its slower thread.", "",
              "| contour | reader+engine (s) | writer (s) | elapsed (s) | JSON: reader+engine | writer "
              "| elapsed | slower |", "|---|---|---|---|---|---|---|---|"]
    for r in rows:
        st, sj = r["stages"], r["stages_json"]
        cells = [f"{d.get(k, 0):.3f}" for d in (st, sj) for k in ("reader+engine", "writer", "elapsed")]
        slowest = max(("reader+engine", "writer"), key=lambda k: st.get(k, 0))
        lines.append(f"| {r['label']} | " + " | ".join(cells) + f" | {slowest} |")
    lines += ["",
              "## Memory", "",
              "cutcom's fast engine streams: its peak memory does not grow with the program "
              "(`cutcom run`, lines+arcs with CDON). The SVG picture keeps every element up to "
              "20,000 of them, then polylines within a bound it states (at most 200,000 points). "
              "JSON keeps its lists after the path (here every decision, `--trace`) in memory up to "
              "1 MB each, then in a temporary file.", "",
              "| blocks | peak memory, text output | peak memory, JSON with `--trace` | peak memory, SVG picture "
              "| SVG time (s) |", "|---|---|---|---|---|"]
    lines += [f"| {n} | {mb(kb)} | {mb(json_kb)} | {mb(svg_kb)} | {svg_s:.2f} |"
              for n, kb, json_kb, svg_kb, svg_s in memory]
    if ref_memory:
        lines += ["", "ref keeps the blocks its window, look-ahead and approach still refer to (and a spare of "
                  "64), not the program: its peak memory does not grow with the program either "
                  "(`cutcom run --engine ref`, the same contours, text output). ref's exact numbers are "
                  "allocated and freed at every operation: `cutcom` is linked with mimalloc, without which "
                  "(glibc's malloc) ref took 15 % longer. Most of its time goes to CORE's "
                  "approximations: converting each output point to its nearest double, and exact signs "
                  "where CORE's floating-point filter cannot decide. That filter's error bound grows with "
                  "the coordinates, not with the differences that matter (the contours below reach 167 m "
                  "along X at 10^5 blocks, 1.7 km at 10^6), so a corner's intersection point gets its coordinates' filters from "
                  "their nearest doubles (ref/src/kernel.hpp, tighten_filters): under CDON the later "
                  "pieces that cross it are then decided by the filter, about half of ref's time before. "
                  "ref is not built profile-guided (only the reader, fast, the writers and the command "
                  "are): its times here move with the machine's speed alone.", "",
                  "| contour | blocks | ref peak memory | ref time (s) | per block (ms) |", "|---|---|---|---|---|"]
        lines += [f"| {label} | {n} | {mb(kb)} | {t:.1f} | {1000 * t / n:.3f} |" for label, n, kb, t in ref_memory]
    lines += ["", "## A parametric program", "",
              "A pocket of 25,000 passes of four blocks under G41, once as a WHILE loop that computes its "
              "coordinates, once written out block by block (`cutcom run FILE -o /dev/null`, whole process, "
              "text output). A loop's lines run from what their first pass recorded (NC-PARAM-EXPR-4).", "",
              "| program | blocks | time (s) | blocks/s |", "|---|---|---|---|"]
    lines += [f"| {name} | {n} | {t:.3f} | {n / t / 1e6:.2f} M |" for name, n, t in pocket]
    if engines:
        lines += ["", "## In process", "",
                  f"`bench/bench_engines` (Google Benchmark), reader and fast engine without output, "
                  f"{a.runs} repetitions; the machine is shared, so the best run is given beside the median.", "",
                  "| benchmark | median blocks/s | best blocks/s |", "|---|---|---|"]
        lines += [f"| {name} | {m / 1e6:.2f} M | {b / 1e6:.2f} M |" for name, m, b in engines]
    if instructions:
        lines += ["", "## Instructions per block", "",
                  "`bench/block_instructions` under valgrind (callgrind's count, the cost of starting the "
                  "process taken out): the reader alone, then the reader and the fast engine on one thread, "
                  "without output; the writers' share is what writing the text or the JSON document (to a "
                  "stream that drops it) adds on the same thread. Unlike times, these counts do not move with "
                  "the machine's load, so they measure small changes. They do not weigh instructions: "
                  "valgrind counts each pass of a `rep movsq` as one, and core and fast copy blocks in loops "
                  "of 16-byte moves instead (the top CMakeLists.txt says why), which count more instructions "
                  "and take less time.", "",
                  "| contour | blocks | reader | fast engine | together | text writer | JSON writer |",
                  "|---|---|---|---|---|---|---|"]
        lines += [f"| {label} | {n} | {r:.0f} | {e:.0f} | {t:.0f} | {tw:.0f} | {jw:.0f} |"
                  for label, n, r, e, t, tw, jw in instructions]
    lines.append("")
    with open(os.path.join(docs, "performance.md"), "w") as f:
        f.write("\n".join(lines))


if __name__ == "__main__":
    main()
