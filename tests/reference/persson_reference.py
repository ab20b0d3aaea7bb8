#!/usr/bin/env python3
"""Independent reference values for sealsim's static engine (Persson & Yang 2008, §2-3).

Written separately from the Rust code and deliberately by other means:
  * F(x0) by direct adaptive quadrature of its defining integral (no E1 split, no table);
  * moments of C(q) by adaptive quadrature (no closed forms);
  * zeta_c by root finding on erf(P0 / 2 sqrt(G)) (no analytic inversion);
  * u1 = ubar + ubar' A/A' with ubar' and A' from central finite differences (no analytic derivative).
Run:  python3 tests/reference/persson_reference.py   (needs numpy + scipy)
The numbers it prints are pasted, with this file named as their source, into tests/physics_reference.rs.
"""
import math
from scipy import integrate, optimize, special

GAMMA = 0.4


def F(x0):
    f = lambda x: (GAMMA + 3 * (1 - GAMMA) * special.erf(x) ** 2) * math.exp(-x * x) / x
    # split at 1 so quad resolves the 1/x end and the Gaussian tail separately
    if x0 < 1:
        a, _ = integrate.quad(f, x0, 1, epsabs=0, epsrel=1e-13, limit=400)
        b, _ = integrate.quad(f, 1, math.inf, epsabs=0, epsrel=1e-13, limit=400)
        return a + b
    a, _ = integrate.quad(f, x0, math.inf, epsabs=0, epsrel=1e-13, limit=400)
    return a


class SelfAffine:
    def __init__(self, hrms, H, q0, q1):
        self.H, self.q0, self.q1 = H, q0, q1
        self.C0 = H / math.pi * hrms**2 / (q0 ** (-2 * H) - q1 ** (-2 * H))

    def C(self, q):
        return self.C0 * q ** (-2 * (1 + self.H))

    def m3(self, a, b):
        v, _ = integrate.quad(lambda lq: math.exp(4 * lq) * self.C(math.exp(lq)), math.log(a), math.log(b),
                              epsabs=0, epsrel=1e-13, limit=200)
        return v

    def hrms2(self, a, b):
        v, _ = integrate.quad(lambda lq: math.exp(2 * lq) * self.C(math.exp(lq)), math.log(a), math.log(b),
                              epsabs=0, epsrel=1e-13, limit=200)
        return 2 * math.pi * v


def contact(surf, E, nu, P0, thr=0.4):
    Es = E / (1 - nu * nu)
    q0, q1 = surf.q0, surf.q1

    def G(z):
        return math.pi / 4 * Es**2 * surf.m3(q0, z * q0)

    def A(z):
        return special.erf(P0 / (2 * math.sqrt(G(z)))) if z > 1 else 1.0

    def ubar(z):
        p = P0 / A(z)
        zq = z * q0
        Fm = {}

        def integrand(ls):  # q = zq * exp(ls)
            q = zq * math.exp(ls)
            w = (math.pi * surf.m3(zq, q)) ** -0.5
            return q**3 * surf.C(q) * w * F(w * p / Es)

        lo = math.log(1 + 1e-12)
        v, _ = integrate.quad(integrand, lo, math.log(q1 / zq), epsabs=0, epsrel=1e-10, limit=400,
                              points=[math.log(1 + 1e-6), math.log(1 + 1e-3), math.log(2)] if q1 / zq > 2 else None)
        return math.sqrt(math.pi) * v

    zc = optimize.brentq(lambda lz: A(math.exp(lz)) - thr, 1e-12, math.log(q1 / q0), xtol=1e-15, rtol=1e-15)
    zc = math.exp(zc)
    h = 1e-4 * zc
    ub = ubar(zc)
    dub = (ubar(zc + h) - ubar(zc - h)) / (2 * h)
    dA = (A(zc + h) - A(zc - h)) / (2 * h)
    u1 = ub + dub * A(zc) / dA
    hc = math.sqrt(surf.hrms2(zc * q0, q1))
    return dict(zeta_c=zc, u_c=u1, ubar_c=ub, hrms_c=hc, lambda_c=2 * math.pi / (zc * q0))


if __name__ == "__main__":
    for x in (0.01, 0.1, 1.0, 2.0):
        print(f"F({x}) = {F(x):.10e}")
    cases = [
        ("paper s3 / wiper", dict(hrms=2e-6, H=0.8, q0=1e4, q1=7.8e9), 10e6, 0.5, 0.2e6),
        ("paper s3, P0=0.05MPa", dict(hrms=2e-6, H=0.8, q0=1e4, q1=7.8e9), 10e6, 0.5, 0.05e6),
        ("paper s3, P0=1MPa", dict(hrms=2e-6, H=0.8, q0=1e4, q1=7.8e9), 10e6, 0.5, 1e6),
        ("H=0.6 hrms=6um P0=0.5MPa", dict(hrms=6e-6, H=0.6, q0=1e4, q1=7.8e9), 10e6, 0.5, 0.5e6),
        ("H=0.9 nu=0.3 E=3MPa", dict(hrms=1e-6, H=0.9, q0=1e5, q1=1e9), 3e6, 0.3, 0.1e6),
    ]
    for name, s, E, nu, P0 in cases:
        r = contact(SelfAffine(**s), E, nu, P0)
        print(name, {k: f"{v:.8e}" for k, v in r.items()})
