"""sealsim's BEM contact solve side by side with aspher and tamaas (driven by bem-peers.sh).

Every solver gets the same seeded self-affine periodic surface, the same E* and mean pressure
(load control), and runs in its own process (wall time of the solve alone, peak RSS of the
process from os.wait4). "Equal accuracy" is judged on the returned pressure field, computed the
same way for every code: each solution is compared with a tight reference (sealsim at
tolerance 1e-12) in A/A0 (pixels with p > 0), the mean gap ū (from the periodic half-space
compliance 2/(E*|q|) applied to the pressure, gap closed on the contact set on average) and the
pressure field (relative L2). A peer setting "matches" sealsim when its errors are no larger
than max(2 × sealsim's, floor) in all three (floors: 1 pixel in A, 1e-9 in ū, 1e-9 in p); the
fastest matching setting is the peer's "best". aspher's settings (preconditioner engine, precision,
its own tolerance 1e-8 or 1e-9) are all tried on 1 thread up to 1024²; its 2-thread runs, and the
runs from 2048² on, use only the 1-thread pick (fastest matching, else most accurate).

Surface: L = 1, n × n, heights h = Σ a(k) cos(2π k·x + φ) with |a| ∝ |k|^-(1+H) for
1 ≤ |k| ≤ n/8 (integer mode numbers; 8 pixels per shortest wavelength, like benches/bem.rs),
H = 0.8, Gaussian amplitudes and uniform phases from numpy's default_rng(seed), rescaled to an
rms slope of 0.1 (spectral). E* = 1 and p̄ = 0.01 = 0.1 E* h'_rms (A/A0 ≈ 0.2). The problem is
scale-free; pixel = 1/n.
"""

import json
import os
import platform
import resource
import subprocess
import sys
import time

import numpy as np

HURST = 0.8
RMS_SLOPE = 0.1
E_STAR = 1.0
P_MEAN = 0.1 * E_STAR * RMS_SLOPE
SEED = 999
REF_TOL = 1e-12
TOL = 1e-8
# (label, solve_nested keywords) — aspher's periodic nested solve; tolerance given separately.
ASPHER_SETTINGS = [
    ("auto/double", dict(precond_engine="auto", precision="double")),
    ("fft/double", dict(precond_engine="fft", precision="double")),
    ("auto/float_then_double", dict(precond_engine="auto", precision="float_then_double")),
]
ASPHER_TOLS = [1e-8, 1e-9]


def surface(n, seed=SEED):
    """The seeded self-affine periodic surface described in the module docstring (heights, L = 1)."""
    rng = np.random.default_rng(seed)
    kx = np.fft.rfftfreq(n, 1.0 / n)
    ky = np.fft.fftfreq(n, 1.0 / n)
    k = np.hypot(kx[None, :], ky[:, None])
    band = (k >= 1) & (k <= n / 8)
    amp = np.zeros_like(k)
    amp[band] = k[band] ** (-(1.0 + HURST))
    spec = amp * (rng.standard_normal(k.shape) + 1j * rng.standard_normal(k.shape))
    h = np.fft.irfft2(spec, s=(n, n))
    # spectral rms slope: sqrt(<|∇h|²>) with ∇ → 2πik (L = 1)
    hk = np.fft.fft2(h)
    kxf = np.fft.fftfreq(n, 1.0 / n)
    k2 = (2 * np.pi) ** 2 * (kxf[None, :] ** 2 + kxf[:, None] ** 2)
    slope = np.sqrt(np.sum(k2 * np.abs(hk) ** 2) / n**4)
    return np.ascontiguousarray(h * (RMS_SLOPE / slope))


def measures(h, p):
    """A/A0, mean gap ū and approach from a pressure field on the surface h (periodic, E*)."""
    n = h.shape[0]
    k = 2 * np.pi * np.hypot(np.fft.rfftfreq(n, 1.0 / n)[None, :], np.fft.fftfreq(n, 1.0 / n)[:, None])
    with np.errstate(divide="ignore"):
        compliance = np.where(k > 0, 2.0 / (E_STAR * k), 0.0)
    u = np.fft.irfft2(np.fft.rfft2(p) * compliance, s=(n, n))
    on = p > 0
    s = np.mean((h - u)[on])
    gap = np.where(on, 0.0, np.maximum(s + u - h, 0.0))
    return dict(area=float(on.mean()), mean_gap=float(gap.mean()), approach=float(h.max() - s))


def errors(h, p, ref_p, ref):
    m = measures(h, p)
    n = h.shape[0]
    return dict(
        dA_pixels=(m["area"] - ref["area"]) * n * n,
        du_rel=(m["mean_gap"] - ref["mean_gap"]) / ref["mean_gap"],
        dp_l2=float(np.linalg.norm(p - ref_p) / np.linalg.norm(ref_p)),
        area=m["area"],
        mean_gap=m["mean_gap"],
    )


# ---- child processes: one solve each, JSON on stdout, pressure to a file ----


def child_aspher(n, mapfile, label, tol, out):
    import aspher

    h = np.fromfile(mapfile, dtype="<f8").reshape(n, n)
    kw = dict(ASPHER_SETTINGS)[label]
    gap = np.ascontiguousarray(-h.ravel())  # aspher: gap0 = -height for a rigid rough indenter
    coarsest = 64 if n >= 64 else n
    t0 = time.perf_counter()
    res = aspher.solve_nested(grid_size=n, gap=gap, p_nominal=P_MEAN, domain_size=1.0, E_star=E_STAR,
                              coarsest=coarsest, tol=tol, backend="periodic", **kw)
    dt = time.perf_counter() - t0
    np.asarray(res.pressure, dtype="<f8").tofile(out)
    # iterations, matvecs and preconditioner applications on the finest level (aspher sums its
    # stages there); a periodic matvec is one FFT convolution, as is an "fft"-engine application
    print(json.dumps(dict(time_s=dt, iterations=f"{res.iterations} ({res.matvec_count} mv + {res.precond_count} pc)",
                          status=str(res.status))))


def child_tamaas(n, mapfile, tol, out):
    import tamaas as tm

    h = np.fromfile(mapfile, dtype="<f8").reshape(n, n)
    model = tm.ModelFactory.createModel(tm.model_type.basic_2d, [1.0, 1.0], [n, n])
    model.E = E_STAR
    model.nu = 0.0
    solver = tm.PolonskyKeerRey(model, h, tol)
    solver.max_iter = 100000
    t0 = time.perf_counter()
    solver.solve(P_MEAN)
    dt = time.perf_counter() - t0
    np.asarray(model.traction, dtype="<f8").reshape(n, n).tofile(out)
    print(json.dumps(dict(time_s=dt, iterations=None)))


# ---- the driver ----


def run_child(cmd, env):
    """Runs cmd, returns (parsed JSON of its last stdout line, peak RSS in MB)."""
    proc = subprocess.Popen(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, env=env, text=True)
    out, err = proc.stdout.read(), proc.stderr.read()
    _, status, usage = os.wait4(proc.pid, 0)
    proc.returncode = os.waitstatus_to_exitcode(status)
    if proc.returncode != 0:
        raise RuntimeError(f"{cmd[:3]} failed ({proc.returncode}): {err.strip()[-500:]}")
    line = [l for l in out.splitlines() if l.startswith("{")][-1]
    js = json.loads(line)
    if js.get("iterations") is None:  # tamaas prints "iter cost error" lines; take the last
        its = [l.split()[0] for l in out.splitlines() if len(l.split()) == 3 and l.split()[0].isdigit()]
        js["iterations"] = int(its[-1]) if its else ""
    return js, usage.ru_maxrss / 1024.0


def load_avg():
    return " ".join(f"{x:.2f}" for x in os.getloadavg())


def main():
    args = sys.argv[1:]
    if args and args[0] == "child-aspher":
        return child_aspher(int(args[1]), args[2], args[3], float(args[4]), args[5])
    if args and args[0] == "child-tamaas":
        return child_tamaas(int(args[1]), args[2], float(args[3]), args[4])
    # driver: bem_peers.py WORKDIR SEALSIM_RUNNER SIZES QUICK
    work, runner, sizes, quick = args[0], args[1], [int(s) for s in args[2].split(",")], args[3] == "1"
    os.makedirs(work, exist_ok=True)
    py = sys.executable
    me = os.path.abspath(__file__)
    threads_list = [1] if quick else [1, 2]
    aspher_settings = ASPHER_SETTINGS[:2] if quick else ASPHER_SETTINGS
    aspher_tols = [TOL] if quick else ASPHER_TOLS
    rows, big, notes = [], [], []
    pick = {}  # n → (setting, tol): aspher's fastest matching (else most accurate) run on 1 thread
    tamaas_last = None  # (n, seconds) of the last tamaas solve, for the > 10 min skip rule

    def sealsim(n, mapfile, tol, threads, out):
        env = dict(os.environ, OMP_NUM_THREADS=str(threads))
        return run_child([runner, mapfile, str(n), repr(1.0 / n), repr(E_STAR), repr(P_MEAN), repr(tol),
                          str(threads), out], env)

    for n in sizes:
        h = surface(n)
        mapfile = os.path.join(work, f"surface-{n}.f64")
        h.astype("<f8").tofile(mapfile)
        print(f"[{time.strftime('%H:%M:%S')}] {n}²: surface h_rms = {h.std():.4e}, load {load_avg()}", flush=True)
        peers = n <= 2048
        ref_out = os.path.join(work, f"ref-{n}.f64")
        if peers:
            ref_json, _ = sealsim(n, mapfile, REF_TOL, 2, ref_out)
            ref_p = np.fromfile(ref_out, dtype="<f8").reshape(n, n)
            ref = measures(h, ref_p)
            print(f"  reference (sealsim 1e-12): A/A0 {ref['area']:.6f}, ū {ref['mean_gap']:.6e}, "
                  f"{ref_json['time_s']:.2f} s", flush=True)
        for threads in (threads_list if peers else [2]):
            env = dict(os.environ, OMP_NUM_THREADS=str(threads))
            out = os.path.join(work, "p.f64")
            load0 = load_avg()
            js, rss = sealsim(n, mapfile, TOL, threads, out)
            if not peers:
                big.append(dict(n=n, threads=threads, time=js["time_s"], rss=rss, it=js["iterations"],
                                coarse=js["coarse_iterations"], area=js["area_fraction"], load=load0))
                print(f"  sealsim {threads} thr: {js['time_s']:.2f} s, {rss:.0f} MB, "
                      f"{js['iterations']}+{js['coarse_iterations']} it", flush=True)
                continue
            e = errors(h, np.fromfile(out, dtype="<f8").reshape(n, n), ref_p, ref)
            mine = dict(solver="sealsim", setting="default", tol=TOL, time=js["time_s"], rss=rss,
                        it=f"{js['iterations']}+{js['coarse_iterations']}", **e)
            group = [mine]
            print(f"  sealsim {threads} thr: {js['time_s']:.3f} s {rss:.0f} MB, dp {e['dp_l2']:.1e}", flush=True)
            # The full aspher grid on 1 thread up to 1024²; on 2 threads, and from 2048² on, only
            # the pick (fastest matching, else most accurate) of 1 thread at this size, or of the
            # previous size (the full grid would take most of an hour there).
            grid = [(label, tol) for label, _ in aspher_settings for tol in aspher_tols]
            if threads > 1 and pick.get(n):
                grid = [pick[n]]
            elif n >= 2048 and pick:
                grid = [pick[max(pick)]]
            for label, tol in grid:
                try:
                    js, rss = run_child([py, me, "child-aspher", str(n), mapfile, label, repr(tol), out], env)
                except RuntimeError as err:
                    notes.append(f"aspher {label} tol {tol:g} at {n}², {threads} thread(s): {err}")
                    continue
                e = errors(h, np.fromfile(out, dtype="<f8").reshape(n, n), ref_p, ref)
                group.append(dict(solver="aspher", setting=label, tol=tol, time=js["time_s"], rss=rss,
                                  it=str(js["iterations"]), status=js["status"], **e))
                print(f"  aspher {label} {tol:g} {threads} thr: {js['time_s']:.3f} s {rss:.0f} MB, "
                      f"dp {e['dp_l2']:.1e}, {js['status']}", flush=True)
            # tamaas: skip where the last size's time scaled by (n/n_last)² · 1.2 exceeds 10 min
            if threads > 1 and n > 512:
                notes.append(f"tamaas not run on 2 threads at {n}²: at 512² its 2-thread time equalled its 1-thread time")
            elif tamaas_last and tamaas_last[1] * (n / tamaas_last[0]) ** 2 * 1.2 > 600:
                notes.append(f"tamaas skipped at {n}², {threads} thread(s): estimated "
                             f"{tamaas_last[1] * (n / tamaas_last[0]) ** 2 * 1.2:.0f} s > 10 min "
                             f"(from {tamaas_last[1]:.0f} s at {tamaas_last[0]}²)")
            else:
                js, rss = run_child([py, me, "child-tamaas", str(n), mapfile, repr(TOL), out], env)
                e = errors(h, np.fromfile(out, dtype="<f8").reshape(n, n), ref_p, ref)
                group.append(dict(solver="tamaas", setting="PKR", tol=TOL, time=js["time_s"], rss=rss, it="", **e))
                print(f"  tamaas {threads} thr: {js['time_s']:.3f} s {rss:.0f} MB, dp {e['dp_l2']:.1e}", flush=True)
                tamaas_last = (n, js["time_s"])
            # the peers' best: fastest setting that matches sealsim's accuracy
            lim_a = max(2 * abs(mine["dA_pixels"]), 1.0)
            lim_u = max(2 * abs(mine["du_rel"]), 1e-9)
            lim_p = max(2 * mine["dp_l2"], 1e-9)
            for r in group:
                r["match"] = (abs(r["dA_pixels"]) <= lim_a and abs(r["du_rel"]) <= lim_u and r["dp_l2"] <= lim_p
                              and r.get("status", "converged") == "converged")
            for solver in ("aspher", "tamaas"):
                ok = [r for r in group if r["solver"] == solver and r["match"]]
                if ok:
                    fastest = min(ok, key=lambda r: r["time"])
                    fastest["best"] = True

            asp = [r for r in group if r["solver"] == "aspher"]
            if threads == 1 and asp:
                ok = [r for r in asp if r["match"]]
                chosen = min(ok, key=lambda r: r["time"]) if ok else min(asp, key=lambda r: r["dp_l2"])
                pick[n] = (chosen["setting"], chosen["tol"])
            for r in group:
                r.update(n=n, threads=threads, ratio=r["time"] / mine["time"], load=f"{load0} → {load_avg()}")
            rows.extend(group)
    return rows, big, notes


def table(rows, big, notes):
    out = []
    if rows:
        out.append("| n² | threads | solver | setting | tol | time (s) | × sealsim | peak RSS (MB) | iterations "
                   "| ΔA (pixels) | ū rel. err. | ‖Δp‖/‖p‖ | matches | load (1-min avg) |")
        out.append("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|")
        for r in rows:
            mark = " **best**" if r.get("best") else ""
            out.append(
                f"| {r['n']}² | {r['threads']} | {r['solver']} | {r['setting']}{mark} | {r['tol']:g} | "
                f"{r['time']:.3f} | {r['ratio']:.2f} | {r['rss']:.0f} | {r['it']} | {r['dA_pixels']:+.0f} | "
                f"{r['du_rel']:+.1e} | {r['dp_l2']:.1e} | {'yes' if r['match'] else 'no'} | {r['load']} |")
        out.append("")
        out.append("Best-vs-sealsim (time of the peer's fastest matching setting / sealsim's time; "
                   "— where no run matched):")
        out.append("")
        out.append("| n² | threads | aspher best | tamaas |")
        out.append("|---|---|---|---|")
        keys = sorted({(r["n"], r["threads"]) for r in rows})
        for n, t in keys:
            g = [r for r in rows if r["n"] == n and r["threads"] == t]
            cell = {}
            for solver in ("aspher", "tamaas"):
                b = [r for r in g if r["solver"] == solver and r.get("best")]
                cell[solver] = f"{b[0]['ratio']:.2f}× ({b[0]['setting']}, tol {b[0]['tol']:g})" if b else "—"
            out.append(f"| {n}² | {t} | {cell['aspher']} | {cell['tamaas']} |")
        out.append("")
    if big:
        out.append("| n² | threads | sealsim time (s) | peak RSS (MB) | iterations (fine + coarse) | A/A0 | load |")
        out.append("|---|---|---|---|---|---|---|")
        for b in big:
            out.append(f"| {b['n']}² | {b['threads']} | {b['time']:.2f} | {b['rss']:.0f} | {b['it']} + {b['coarse']} "
                       f"| {b['area']:.4f} | {b['load']} |")
        out.append("")
    for note in notes:
        out.append(f"- {note}")
    return "\n".join(out)


if __name__ == "__main__":
    result = main()
    if result is not None:
        text = table(*result)
        print()
        print(text)
        with open(os.path.join(sys.argv[1], "table.md"), "w") as f:
            f.write(text + "\n")
