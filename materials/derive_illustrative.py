#!/usr/bin/env python3
"""Derives the illustrative entries of sealsim's material library (materials/*.toml).

No published Prony series for seal compounds was found, so every entry is ILLUSTRATIVE and built the
same way from a few sourced or clearly assumed numbers:

1. Modulus at the hardness-test time scale (3 s, 23 C) from the nominal Shore A grade with Gent's
   relation, A.N. Gent (1958), "On the relation between indentation hardness and Young's modulus",
   in the form commonly quoted: E [MPa] = 0.0981 (56 + 7.62336 S) / (0.137505 (254 - 2.54 S)).
2. Relaxation in the Chasset-Thirion power-law form E(t) = E_inf [1 + (t/tau0)^-m] with ASSUMED
   m = 0.10 and tau0 = 1e-3 s (the same for every compound: no per-compound data were found),
   calibrated so that E(3 s) equals the Gent modulus.
3. That curve, sampled at 20 points per decade over 1e-6 s .. 1e12 s, fitted with E_inf and one Prony
   term per decade (tau = 1e-7 .. 1e12 s) by non-negative least squares on relative residuals
   (Lawson-Hanson, scipy.optimize.nnls). The fitted E_inf is a few per cent above the Chasset-Thirion
   E_inf: it holds the (slow) relaxation beyond 1e12 s, which the data window does not see.
4. WLF with the "universal" constants C1 = 17.44, C2 = 51.6 K at Tref = T_g (Williams, Landel & Ferry,
   J. Am. Chem. Soc. 77 (1955) 3701), moved to Tref = 23 C exactly:
   C2' = C2 + (Tref - T_g), C1' = C1 C2 / C2'.

Run:  python3 materials/derive_illustrative.py --write   (needs numpy, scipy) — rewrites the Prony
tables, WLF constants and fit residuals of the TOML files from COMPOUNDS below (the other numbers and
their sources are in COMPOUNDS too). Without --write it only prints them.
"""
import math
import numpy as np
from scipy.optimize import nnls

M, TAU0, T_TEST = 0.10, 1e-3, 3.0
C1G, C2G, TREF = 17.44, 51.6, 296.15


def gent(shore):
    return 0.0981 * (56 + 7.62336 * shore) / (0.137505 * (254 - 2.54 * shore)) * 1e6


def derive(shore, tg_c):
    e_test = gent(shore)
    e_inf = e_test / (1 + (T_TEST / TAU0) ** -M)
    t = np.logspace(-6, 12, 18 * 20 + 1)
    target = e_inf * (1 + (t / TAU0) ** -M)
    taus = np.logspace(-7, 12, 20)
    a = np.hstack([np.ones((len(t), 1)), np.exp(-t[:, None] / taus[None, :])]) / target[:, None]
    sol, _ = nnls(a, np.ones(len(t)))
    rel = np.abs(a @ sol - 1)
    e_inf_ct, e_inf, coef = e_inf, sol[0], sol[1:]
    c2 = C2G + (TREF - (tg_c + 273.15))
    c1 = C1G * C2G / c2
    return dict(e_test=e_test, e_inf=e_inf, e_inf_ct=e_inf_ct, terms=[(c, tau) for c, tau in zip(coef, taus) if c > 0],
                max_rel=rel.max(), rms_rel=math.sqrt((rel ** 2).mean()), c1=c1, c2=c2)


HANDBOOK = ("Handbook of Plastics Technologies: The Complete Guide to Properties and Performance "
            "(McGraw-Hill, 2006)")
KOMMLING = ("A. Kömmling, M. Jaunich, D. Wolff, 'Ageing and lifetime prediction of O-ring seals made of "
            "HNBR, EPDM and FKM', Fall Rubber Colloquium (Kautschuk Herbst Kolloquium), Hanover, 2016 "
            "(BAM OPUS4-38480)")
CTE_ASSUMED = ("assumed 160e-6 1/K, of the order of the sourced NBR and EPDM values; no source found for "
               "this polymer; illustrative")

# id, name, Shore A grade, T_g [C] with source, linear CTE [1/K] with source, ageing or None
COMPOUNDS = [
    dict(id="nbr-70", name="NBR (nitrile rubber, medium acrylonitrile), 70 Shore A", shore=70,
         tg=-34, tg_src=f"{HANDBOOK}, Table 4.2: nitrile rubber, medium nitrile, T_g = -34 C",
         cte=165e-6, cte_src="midpoint of the 150-180e-6 1/K given for NBR by NETZSCH (Polymers, "
         "NBR material page, analyzing-testing.netzsch.com); illustrative for a given compound",
         ageing=None),
    dict(id="hnbr-75", name="HNBR (hydrogenated nitrile rubber), 75 Shore A", shore=75,
         tg=-30, tg_src=f"{HANDBOOK}, Table 4.2: hydrogenated nitrile, T_g = -30 C",
         cte=160e-6, cte_src=CTE_ASSUMED, ageing=None),
    dict(id="fkm-75", name="FKM (fluoroelastomer), 75 Shore A", shore=75,
         tg=-10, tg_src="Encyclopaedia Britannica, 'elastomer', table of elastomers: fluoroelastomer, "
         "T_g = -10 C (copolymer/terpolymer grades differ)",
         cte=160e-6, cte_src=CTE_ASSUMED,
         ageing=dict(ea=38e3, rate=-math.log(1 - 0.65) / (40 * 365.25 * 86400), tref=60.0,
                     src="Ea = 38 kJ/mol: compression stress relaxation of FKM 75 Shore A, European "
                     "Sealing Association / Cetim round robin, Valve World (August 2023) p. 53; "
                     f"k_ref at 60 C from {KOMMLING}: about 40 years to 65 % compression set at 60 C, "
                     "converted with CS = 1 - exp(-k t) (an assumption); the two numbers come from "
                     "different studies and properties: illustrative")),
    dict(id="epdm-70", name="EPDM (ethylene propylene diene rubber), 70 Shore A", shore=70,
         tg=-55, tg_src=f"{HANDBOOK}, Table 4.2: EPDM, T_g = -55 C",
         cte=160e-6, cte_src="Wikipedia, 'EPDM rubber', properties table: linear thermal expansion "
         "160 um/(m K) (read from a mirror); illustrative for a given compound", ageing=None),
    dict(id="vmq-70", name="VMQ (silicone rubber), 70 Shore A", shore=70,
         tg=-127, tg_src=f"{HANDBOOK}, Table 4.1: silicone rubber, T_g = -127 C",
         cte=200e-6, cte_src="estimated: an unfilled silicone rubber can exceed 300e-6 1/K and fillers "
         "reduce the CTE by 30-50 % (engineeringniche.com, 'Designing rubber and elastomeric materials "
         "to accommodate thermal expansion'); 200e-6 1/K taken for a filled compound, illustrative",
         ageing=None),
    dict(id="cr-70", name="CR (polychloroprene), 70 Shore A", shore=70,
         tg=-45, tg_src=f"{HANDBOOK}, Table 4.2: polychloroprene, T_g = -45 C",
         cte=160e-6, cte_src=CTE_ASSUMED, ageing=None),
]


def toml_for(c):
    d = derive(c["shore"], c["tg"])
    lines = [
        f"# {c['name']} — ILLUSTRATIVE entry derived by materials/derive_illustrative.py (see its",
        "# docstring): no published Prony series for this class of seal compound was found.",
        "[material]",
        f'name = "{c["name"]} (illustrative)"',
        'status = "illustrative"',
        "poisson_ratio = 0.5",
        f'long_term_modulus = "{d["e_inf"] / 1e6:.6g} MPa"',
        "prony = [",
    ]
    lines += [f'    {{ modulus = "{m / 1e6:.6g} MPa", tau = "{tau:.0e} s" }},' for m, tau in d["terms"]]
    lines += [
        "]",
        f'glass_transition = "{c["tg"]} C"',
        f'thermal_expansion = "{c["cte"]:.3g} 1/K"',
        "",
        "[material.shift]",
        'kind = "wlf"',
        'reference_temperature = "23 C"',
        f"c1 = {d['c1']:.6g}",
        f'c2 = "{d["c2"]:.6g} K"',
    ]
    if c["ageing"]:
        a = c["ageing"]
        lines += ["", "[material.ageing]", f'activation_energy = "{a["ea"] / 1e3:g} kJ/mol"',
                  f'rate = "{a["rate"]:.3e} 1/s"', f'reference_temperature = "{a["tref"]:g} C"']
    gent_src = (f"E(3 s, 23 C) = {d['e_test'] / 1e6:.4f} MPa from Gent's relation at {c['shore']} Shore A "
                "(A.N. Gent 1958, 'On the relation between indentation hardness and Young's modulus', "
                "form as commonly quoted; the grade is nominal)")
    prov = {
        "poisson_ratio": "rubber is nearly incompressible; 0.5 as in Persson & Yang 2008, section 3; "
                         "illustrative",
        "long_term_modulus": f"NNLS fit (with the prony terms) to the Chasset-Thirion curve "
                             f"E_inf [1 + (t/tau0)^-m], E_inf = E(3 s)/(1 + (3 s/tau0)^-m) = "
                             f"{d['e_inf_ct'] / 1e6:.4f} MPa with {gent_src}, assumed m = {M}, "
                             f"tau0 = {TAU0:g} s; the fitted value also holds the relaxation beyond "
                             "1e12 s; illustrative",
        "prony": f"NNLS fit, one term per decade (tau 1e-7 .. 1e12 s), to that Chasset-Thirion curve on "
                 f"1e-6 .. 1e12 s at 23 C: max deviation {100 * d['max_rel']:.2f} %, "
                 f"rms {100 * d['rms_rel']:.2f} %; illustrative",
        "shift": "WLF universal constants C1 = 17.44, C2 = 51.6 K at Tref = T_g (Williams, Landel & "
                 "Ferry, J. Am. Chem. Soc. 77 (1955) 3701) moved exactly to Tref = 23 C: "
                 "C2' = C2 + Tref - T_g, C1' = C1 C2/C2', with T_g below; the constants hold from T_g to about T_g + 50 K (IUPAC Gold Book, WLF equation), beyond that an extrapolation; "
                 "illustrative",
        "glass_transition": c["tg_src"],
        "thermal_expansion": c["cte_src"],
    }
    if c["ageing"]:
        prov["ageing"] = c["ageing"]["src"]
    lines += ["", "[material.provenance]"]
    lines += [f'{k} = "{v}"' for k, v in prov.items()]
    return "\n".join(lines) + "\n", d


if __name__ == "__main__":
    import os
    import sys
    here = os.path.dirname(os.path.abspath(__file__))
    for c in COMPOUNDS:
        text, d = toml_for(c)
        print(f"{c['id']}: E(3 s) = {d['e_test']/1e6:.4f} MPa, E_inf = {d['e_inf']/1e6:.4f} MPa, "
              f"fit max {d['max_rel']:.2e} rms {d['rms_rel']:.2e}, C1' = {d['c1']:.4f}, C2' = {d['c2']:.2f} K")
        if "--write" in sys.argv:
            with open(os.path.join(here, c["id"] + ".toml"), "w") as f:
                f.write(text)
