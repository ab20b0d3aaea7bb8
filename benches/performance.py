#!/usr/bin/env python3
"""The performance page (docs/src/performance.md) from measurements, with their provenance.

Every figure on the page lives in the committed store benches/results/measurements.json with
its value, the date (UTC) it was measured, the commit it was measured at (`-dirty` when the
tree had changes outside this generator's own files), the machine (CPU model, cores, RAM,
kernel, rustc) and the load average then. The page is rendered from the store and the template
benches/performance.md.in (the prose, the rows' descriptions and targets); a test
(tests/cli/generate_reference.rs) runs `render --check`, so the page cannot drift from the store.

Python 3 standard library only. From the repository's root:

    python3 benches/performance.py bench engine life study -- --quick
        cargo bench for those benches under the timing lock, then `record` their figures
    python3 benches/performance.py record [--bench NAME ...] [--load TEXT] [--commit HASH]
        the figures of criterion's latest results (target/criterion/*/new/) into the store
    python3 benches/performance.py record-command ID [--repeat K] [--cases N] -- CMD ...
        a whole process timed, best of K (wall clock); with --cases, also as cases per minute
    python3 benches/performance.py record-study ID STUDY --samples N --threads T [--repeat K]
        `sealsim study` on a temporary copy of STUDY with `samples = N`, timed as above
    python3 benches/performance.py record-legacy ID TEXT [--search S] [--value V --unit U]
        a figure that cannot be re-measured here, dated by the commit that last changed it in
        docs/src/performance.md (followed into README.md, where the page lived before)
    python3 benches/performance.py render [--check]
        writes docs/src/performance.md; --check only compares (exit 1 when it differs)
"""

import argparse
import datetime
import hashlib
import json
import os
import platform
import re
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
STORE = ROOT / "benches/results/measurements.json"
TEMPLATE = ROOT / "benches/performance.md.in"
PAGE = ROOT / "docs/src/performance.md"
BEM_PEERS = ROOT / "benches/results/bem-peers.md"
CRITERION = ROOT / "target/criterion"
LOCK = "/tmp/sealsim-timing.lock"
# The generator's own files: changing them does not change what a benchmark measures, so they
# do not make a measurement "-dirty".
OWN_FILES = [
    "benches/performance.py",
    "benches/performance.md.in",
    "benches/results/measurements.json",
    "docs/src/performance.md",
]
# Where the page lived before docs/src/performance.md (issue 33 moved it out of the README).
PAGE_HISTORY = ["docs/src/performance.md", "README.md"]
LEGACY_MACHINE = "vm-unrecorded"
LEGACY_MACHINE_TEXT = (
    "the 2-core VM of that date (not recorded; the page's header then read "
    "“AMD EPYC, 2 cores, Linux 6.18, Rust 1.95”; load not recorded)"
)

# The criterion benchmarks the page quotes: store id -> (bench target, criterion full id,
# divisor: the iterations' work in units of the figure, e.g. a batch of 64 lookups[, the cases
# an iteration runs, for a rate in cases per minute]).
BENCHES = {
    "engine.exact": ("engine", "exact critical junction (paper case, P0 = 0.2 MPa)", 1),
    "engine.table-build": ("engine", "contact table build (paper surface)", 1),
    "engine.table-lookup": ("engine", "contact table lookup (64 pressures, per batch)", 64),
    "engine.em-pu": ("engine", "effective medium: P(u) (paper case, 0.2 MPa)", 1),
    "engine.em-bruggeman": ("engine", "effective medium: Bruggeman solve (paper case, 0.2 MPa)", 1),
    "engine.em-lookup": ("engine", "effective medium: table lookup (paper case, 0.2 MPa)", 1),
    "engine.em-table-build": ("engine", "slow/effective medium: table build (paper surface)", 1),
    "material.prony-eval": ("material", "E(t), 30-term Prony series", 1),
    "material.recursive-update": ("material", "RelaxationState::step, 30 terms", 1),
    "material.fit-plain": ("material", "Prony fit, 100 relaxation points, 3/decade, plain NNLS", 1),
    "material.fit-gcv": ("material", "Prony fit, 100 relaxation points, 3/decade, GCV", 1),
    "material.fit-gcv-coarse": ("material", "Prony fit, 100 relaxation points, 1/decade, GCV", 1),
    "life.headline": (
        "life",
        "30-year O-ring life run with ageing and set (headline scenario, critical-junction, follow)",
        1,
    ),
    "life.unaged-relaxed": ("life", "30-year O-ring life run without ageing, asperity modulus relaxed", 1),
    "life.unaged-follow": ("life", "30-year O-ring life run without ageing (follow)", 1),
    "life.no-failure": ("life", "30-year O-ring life run, no failure criteria", 1),
    "life.gasket-clean": ("life", "30-year gasket life run in clean oil", 1),
    "life.gasket-clog": ("life", "30-year gasket life run with clogging, reroute = false", 1),
    "life.gasket-clog-reroute": ("life", "30-year gasket life run with clogging, reroute = true", 1),
    "life.epdm-cycles": ("life", "cycles/30-year EPDM outdoor run, daily and yearly cycles", 1),
    "study.mc1000-1t": ("study", "study/headline monte carlo, 1000 cases, 1 thread(s)", 1, 1000),
    "study.mc1000-2t": ("study", "study/headline monte carlo, 1000 cases, 2 thread(s)", 1, 1000),
}


def sh(*args, check=True):
    """The standard output of a command run at the repository's root, stripped."""
    out = subprocess.run(args, cwd=ROOT, capture_output=True, text=True, check=check)
    return out.stdout.strip()


def commit_now():
    """HEAD's short hash, `-dirty` when files other than the generator's own have changed."""
    head = sh("git", "rev-parse", "--short", "HEAD")
    excludes = [f":(exclude){f}" for f in OWN_FILES]
    dirty = sh("git", "status", "--porcelain", "--untracked-files=no", "--", ".", *excludes)
    return head + ("-dirty" if dirty else "")


def machine_now():
    """(id, description) of this machine: the id is a hash of the description, so that two
    engineers measuring on the same machine agree and branches merge without renumbering."""
    cpu = "unknown CPU"
    logical = 0
    try:
        for line in Path("/proc/cpuinfo").read_text().splitlines():
            if line.startswith("model name") and cpu == "unknown CPU":
                cpu = line.split(":", 1)[1].strip()
            if line.startswith("processor"):
                logical += 1
    except OSError:
        pass
    ram = "unknown RAM"
    try:
        for line in Path("/proc/meminfo").read_text().splitlines():
            if line.startswith("MemTotal:"):
                ram = f"{int(line.split()[1]) / 1024 / 1024:.1f} GiB RAM"
    except OSError:
        pass
    try:
        rustc = sh("rustc", "-V")
    except (OSError, subprocess.CalledProcessError):
        rustc = "rustc unknown"
    cores = logical or os.cpu_count() or 0
    desc = f"{cpu}, {cores} cores, {ram}, Linux {platform.release()}, {rustc}"
    return "vm-" + hashlib.sha1(desc.encode()).hexdigest()[:6], desc


def load_now():
    """The 1, 5 and 15-minute load averages."""
    try:
        return " ".join(Path("/proc/loadavg").read_text().split()[:3])
    except OSError:
        return "unknown"


def utc(ts=None):
    moment = datetime.datetime.fromtimestamp(ts if ts is not None else time.time(), datetime.timezone.utc)
    return moment.strftime("%Y-%m-%dT%H:%M:%SZ")


def read_store():
    if STORE.exists():
        return json.loads(STORE.read_text())
    return {"machines": {}, "figures": {}}


def write_store(store):
    STORE.parent.mkdir(parents=True, exist_ok=True)
    STORE.write_text(json.dumps(store, indent=1, sort_keys=True, ensure_ascii=False) + "\n")


def put(store, fid, figure, machine=None):
    if machine is not None:
        store["machines"][machine[0]] = machine[1]
    store["figures"][fid] = figure
    print(f"{fid}: {figure.get('text') or fmt_value(figure)} ({figure['date']}, {figure['commit']})")


# --- record -------------------------------------------------------------------------------

def criterion_results():
    """criterion's latest result of each benchmark: full id -> (estimates, mtime)."""
    found = {}
    for meta in CRITERION.glob("**/new/benchmark.json"):
        full_id = json.loads(meta.read_text())["full_id"]
        est = meta.parent / "estimates.json"
        if est.exists():
            found[full_id] = (json.loads(est.read_text()), est.stat().st_mtime)
    return found


def cmd_record(args):
    store = read_store()
    machine = machine_now()
    commit = args.commit or commit_now()
    load = args.load or load_now()
    results = criterion_results()
    now = time.time()
    recorded = 0
    for fid, (bench, full_id, per, *cases) in BENCHES.items():
        if args.bench and bench not in args.bench:
            continue
        if full_id not in results:
            print(f"{fid}: no criterion result for “{full_id}” (not run)", file=sys.stderr)
            continue
        est, mtime = results[full_id]
        if now - mtime > args.max_age_hours * 3600:
            print(f"{fid}: criterion's result is older than {args.max_age_hours} h; skipped", file=sys.stderr)
            continue
        # criterion's headline figure: the slope of a linear sampling, else the mean (ns)
        kind = "slope" if est.get("slope") else "mean"
        e = est[kind]
        ci = e["confidence_interval"]
        fig = {
            "value": e["point_estimate"] * 1e-9 / per,
            "unit": "s",
            "ci95": [ci["lower_bound"] * 1e-9 / per, ci["upper_bound"] * 1e-9 / per],
            "date": utc(mtime),
            "commit": commit,
            "machine": machine[0],
            "load": load,
            "source": f"cargo bench --bench {bench}: “{full_id}”, criterion {kind}"
            + (f" / {per}" if per != 1 else ""),
        }
        if cases:
            fig["cases"] = cases[0]
        put(store, fid, fig, machine)
        recorded += 1
    write_store(store)
    print(f"{recorded} figures recorded into {STORE.relative_to(ROOT)}")
    return 0 if recorded else 1


def cmd_bench(args):
    """cargo bench under the timing lock, then record what it measured."""
    import fcntl

    with open(LOCK, "a") as lock:
        fcntl.flock(lock, fcntl.LOCK_EX)
        before = load_now()
        commit = commit_now()
        cmd = ["cargo", "bench"]
        for b in args.benches:
            cmd += ["--bench", b]
        cmd += ["--", *args.criterion_args]
        subprocess.run(cmd, cwd=ROOT, check=True)
        after = load_now()
    ns = argparse.Namespace(
        commit=commit,
        load=f"{before} before, {after} after",
        bench=args.benches,
        max_age_hours=24,
    )
    return cmd_record(ns)


def time_best(cmd, repeat):
    """The fastest of `repeat` runs: (wall clock, the CPU time of that run: user + system), s."""
    best = (float("inf"), 0.0)
    for _ in range(repeat):
        start = time.perf_counter()
        proc = subprocess.Popen(cmd, cwd=ROOT, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        _, status, usage = os.wait4(proc.pid, 0)
        wall = time.perf_counter() - start
        proc.returncode = os.waitstatus_to_exitcode(status)
        if proc.returncode != 0:
            sys.exit(f"{' '.join(cmd)}: exit {proc.returncode}")
        best = min(best, (wall, usage.ru_utime + usage.ru_stime))
    return best


def record_timed(args, fid, cmd, shown):
    store = read_store()
    machine = machine_now()
    commit = args.commit or commit_now()
    before = load_now()
    best, cpu = time_best(cmd, args.repeat)
    figure = {
        "value": best,
        "cpu_s": cpu,
        "unit": "s",
        "date": utc(),
        "commit": commit,
        "machine": machine[0],
        "load": f"{before} before, {load_now()} after",
        "source": f"whole process, wall clock, best of {args.repeat}: {shown}",
    }
    if args.cases:
        figure["cases"] = args.cases
    put(store, fid, figure, machine)
    write_store(store)
    return 0


def cmd_record_command(args):
    cmd = args.command
    if not cmd:
        sys.exit("record-command: no command given after --")
    return record_timed(args, args.id, cmd, " ".join(cmd))


def cmd_record_study(args):
    study = (ROOT / args.study).resolve()
    text = study.read_text()
    text, n = re.subn(r"(?m)^samples\s*=\s*\d+", f"samples = {args.samples}", text)
    if n != 1:
        sys.exit(f"record-study: {args.study} has no single `samples = N` line")
    # the copy sits elsewhere: its base must be absolute
    text, n = re.subn(
        r'(?m)^base\s*=\s*"([^"]+)"',
        lambda m: f'base = "{(study.parent / m.group(1)).resolve()}"',
        text,
    )
    if n != 1:
        sys.exit(f"record-study: {args.study} has no single `base = \"…\"` line")
    args.cases = args.samples
    with tempfile.TemporaryDirectory() as tmp:
        copy = Path(tmp) / study.name
        copy.write_text(text)
        cmd = [args.bin, "study", str(copy), "--threads", str(args.threads)]
        shown = (
            f"sealsim study {args.study} (samples = {args.samples} in a temporary copy) "
            f"--threads {args.threads}"
        )
        return record_timed(args, args.id, cmd, shown)


def cmd_record_legacy(args):
    """A figure from an earlier page, with the date and commit that last changed it there."""
    search = args.search or args.text
    page, before = PAGE_HISTORY
    found = sh("git", "log", "-1", "--format=%H %cs", "-S", search, "HEAD", "--", page)
    if found:
        # a figure moved into the page from the README: the README's last change to it dates it
        moved = found.split()[0]
        earlier = subprocess.run(
            ["git", "show", f"{moved}^:{before}"], cwd=ROOT, capture_output=True, text=True
        ).stdout
        if search in earlier:
            found = sh("git", "log", "-1", "--format=%H %cs", "-S", search, f"{moved}^", "--", before) or found
    if not found:
        sys.exit(f"record-legacy: “{search}” is in no commit of {page}")
    commit, date = found.split()
    store = read_store()
    store["machines"][LEGACY_MACHINE] = LEGACY_MACHINE_TEXT
    figure = {
        "text": args.text,
        "date": date,
        "commit": commit[:7],
        "machine": LEGACY_MACHINE,
        "load": args.load,
        "source": f"not re-measured: as last written in the page (git log -1 -S '{search}' "
        f"-- {' '.join(PAGE_HISTORY)}, following the move)",
    }
    if args.value is not None:
        figure["value"] = args.value
        figure["unit"] = args.unit
    put(store, args.id, figure)
    write_store(store)
    return 0


# --- render -------------------------------------------------------------------------------

def sig3(x):
    """x to 3 significant figures, without an exponent."""
    if x == 0:
        return "0"
    digits = max(0, 2 - int(f"{abs(x):e}".split("e")[1]))
    return f"{x:.{digits}f}"


def fmt_value(fig):
    if "text" in fig:
        return fig["text"]
    v, unit = fig["value"], fig["unit"]
    if unit == "s":
        for scale, name in ((1e-6, "ns"), (1e-3, "µs"), (1.0, "ms")):
            if v < scale:
                return f"{sig3(v / scale * 1e3)} {name}"
        return f"{sig3(v)} s"
    return f"{sig3(v)} {unit}"


def value_of(store, fid):
    fig = figure(store, fid)
    if "value" not in fig:
        raise SystemExit(f"render: {fid} has no numeric value (a ratio needs one)")
    return fig["value"]


def figure(store, fid):
    try:
        return store["figures"][fid]
    except KeyError:
        raise SystemExit(f"render: the template names {fid}, which is not in {STORE.relative_to(ROOT)}")


def provenance(fig):
    """`date · commit · machine`, with the load average when it was recorded."""
    text = f"{fig['date'][:10]} · {fig['commit']} · {fig['machine']}"
    load = fig.get("load")
    if not load:
        return text
    # "a b c before, d e f after" (1, 5, 15-minute averages): the 1-minute ones
    numbers = re.findall(r"(\d+\.\d+) \d+\.\d+ \d+\.\d+", load)
    if numbers:
        return f"{text} · load {' → '.join(numbers)}"
    return f"{text} · {load}"


TOKEN = re.compile(r"\{\{([a-z]+:)?([^}]*)\}\}")


HEADER = (
    "<!-- Generated from benches/results/measurements.json and benches/performance.md.in by "
    "`python3 benches/performance.py render`; do not edit by hand. -->\n\n"
)


def render(store):
    template = TEMPLATE.read_text()
    out = []
    for line in template.splitlines():
        used = []

        def sub(m):
            kind, arg = (m.group(1) or "")[:-1], m.group(2)
            if kind == "" and arg in ("prov", "machines", "bem-peers"):
                return m.group(0)
            if kind == "":
                used.append(arg)
                return fmt_value(figure(store, arg))
            if kind == "inline":
                used.append(arg)
                fig = figure(store, arg)
                return f"{fmt_value(fig)} ({provenance(fig)})"
            if kind == "ratio":
                a, b = arg.split("/")
                used.extend([a, b])
                return f"{value_of(store, a) / value_of(store, b):.2f}×"
            if kind == "cpu":
                used.append(arg)
                return fmt_value({"value": figure(store, arg)["cpu_s"], "unit": "s"})
            if kind == "rate":
                used.append(arg)
                fig = figure(store, arg)
                rate = fig["cases"] / fig["value"] * 60
                return f"{sig3(rate)} cases/min"
            raise SystemExit(f"render: unknown placeholder {m.group(0)}")

        line = TOKEN.sub(sub, line)
        if "{{prov}}" in line:
            line = line.replace("{{prov}}", prov_cell(store, used))
        if line.strip() == "{{machines}}":
            out.extend(machines_table(store))
            continue
        if line.strip() == "{{bem-peers}}":
            if BEM_PEERS.exists():
                out.extend(bem_peers(store))
            continue
        out.append(line)
    return HEADER + "\n".join(out) + "\n"


def bem_peers(store):
    """benches/results/bem-peers.md with the page's provenance on every row of its table: the
    date and commit its header states, and the machine of the store whose description names its
    kernel (else the unrecorded one)."""
    text = BEM_PEERS.read_text().rstrip("\n").splitlines()
    date = commit = None
    kernel = None
    for line in text:
        m = re.match(r"- date: (\d{4}-\d{2}-\d{2}).*commit ([0-9a-f]{7,})", line)
        if m:
            date, commit = m.group(1), m.group(2)
        m = re.match(r"- machine: .*kernel (\S+)", line)
        if m:
            kernel = m.group(1)
    machine = LEGACY_MACHINE
    for mid, desc in store.get("machines", {}).items():
        if kernel and kernel in str(desc):
            machine = mid
    out = []
    for line in text:
        if line.startswith("| n² |"):
            line = "| what |" + line[len("| n² |"):] + " measured |"
        elif line.startswith("|---"):
            line += "---|"
        elif line.startswith("| ") and date and commit:
            line += f" {date} · {commit} · {machine} |"
        out.append(line)
    return out


def prov_cell(store, used):
    """The provenance of a row's figures: one `date · commit · machine` when they share it,
    else each provenance with the figures it covers."""
    groups = {}
    for fid in dict.fromkeys(used):
        fig = figure(store, fid)
        groups.setdefault(provenance(fig), []).append(fmt_value(fig))
    if len(groups) == 1:
        return next(iter(groups))
    return "; ".join(f"{p} ({', '.join(values)})" for p, values in groups.items())


def machines_table(store):
    rows = ["| machine | what |", "|---|---|"]
    for mid, desc in sorted(store["machines"].items()):
        rows.append(f"| {mid} | {desc} |")
    return rows


def cmd_render(args):
    page = render(read_store())
    if args.check:
        target = Path(args.page) if args.page else PAGE
        if not target.exists() or target.read_text() != page:
            print(
                f"{PAGE.relative_to(ROOT)} differs from what benches/performance.md.in and "
                f"{STORE.relative_to(ROOT)} give: run `python3 benches/performance.py render`",
                file=sys.stderr,
            )
            return 1
        return 0
    PAGE.write_text(page)
    print(f"wrote {PAGE.relative_to(ROOT)}")
    return 0


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    sub = p.add_subparsers(dest="cmd", required=True)

    b = sub.add_parser("bench", help="cargo bench under the timing lock, then record")
    b.add_argument("benches", nargs="+")
    b.set_defaults(func=cmd_bench)

    r = sub.add_parser("record", help="criterion's latest results into the store")
    r.add_argument("--bench", action="append", help="only this bench target (repeatable)")
    r.add_argument("--load", help="the load average while measuring (default: now)")
    r.add_argument("--commit", help="the commit measured (default: HEAD, -dirty if dirty)")
    r.add_argument("--max-age-hours", type=float, default=24)
    r.set_defaults(func=cmd_record)

    c = sub.add_parser("record-command", help="a whole process, best of K")
    c.add_argument("id")
    c.add_argument("--repeat", type=int, default=5)
    c.add_argument("--cases", type=int, help="cases the command runs (for cases/min)")
    c.add_argument("--commit", help="the commit the binary was built from (default: HEAD)")
    c.set_defaults(func=cmd_record_command)

    s = sub.add_parser("record-study", help="`sealsim study` with N samples, best of K")
    s.add_argument("id")
    s.add_argument("study")
    s.add_argument("--samples", type=int, required=True)
    s.add_argument("--threads", type=int, required=True)
    s.add_argument("--repeat", type=int, default=3)
    s.add_argument("--commit", help="the commit the binary was built from (default: HEAD)")
    s.add_argument("--bin", default=str(ROOT / "target/release/sealsim"))
    s.set_defaults(func=cmd_record_study)

    g = sub.add_parser("record-legacy", help="a figure not re-measured, dated from git")
    g.add_argument("id")
    g.add_argument("text", help="the figure as the page shows it")
    g.add_argument("--search", help="the string to find in the page's history (default: TEXT)")
    g.add_argument("--value", type=float, help="its value in SI units (for ratios)")
    g.add_argument("--unit", default="s")
    g.add_argument("--load", help="the load then, where the page stated it")
    g.set_defaults(func=cmd_record_legacy)

    d = sub.add_parser("render", help="docs/src/performance.md from the store and the template")
    d.add_argument("--check", action="store_true", help="only compare; exit 1 when it differs")
    d.add_argument("--page", help="with --check: compare this file instead of the page")
    d.set_defaults(func=cmd_render)

    # what follows `--` is the command (record-command) or criterion's arguments (bench)
    argv = sys.argv[1:]
    rest = []
    if "--" in argv:
        at = argv.index("--")
        argv, rest = argv[:at], argv[at + 1 :]
    args = p.parse_args(argv)
    args.command = args.criterion_args = rest
    sys.exit(args.func(args))


if __name__ == "__main__":
    main()
