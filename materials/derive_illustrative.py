#!/usr/bin/env python3
"""Derives the illustrative entries of sealsim's material library (materials/*.toml).

No published Prony series for seal compounds was found, so every entry is ILLUSTRATIVE and built the
same way from a few sourced or clearly assumed numbers:

1. Modulus at the hardness-test time scale (3 s, 23 C) from the nominal Shore A grade with Gent's
   relation, A.N. Gent (1958), "On the relation between indentation hardness and Young's modulus",
   in the form commonly quoted: E [MPa] = 0.0981 (56 + 7.62336 S) / (0.137505 (254 - 2.54 S)).
2. Rubbery relaxation in the Chasset-Thirion power-law form E_r(t) = E_inf [1 + (t/tau0)^-m] with
   tau0 = 1e-3 s ASSUMED for every compound and m per compound (COMPOUNDS key "m", default
   M_DEFAULT = 0.10, ASSUMED: no per-compound data were found; set it from compression stress
   relaxation data when available). The power law is capped at short times by writing t + tau_g for
   t, so that it stays finite: E_r(t) = E_inf [1 + ((t + tau_g)/tau0)^-m].
3. The glass transition at short times: a glassy modulus E_g (COMPOUNDS key "e_g", default
   E_GLASS_DEFAULT = 2 GPa, ILLUSTRATIVE: amorphous polymers are of the order of 1-3 GPa below T_g)
   reached through a stretched exponential (Kohlrausch-Williams-Watts) fraction
   phi(t) = exp(-(t/tau_g)^beta), beta = BETA = 0.4 (ASSUMED, within the 0.3-0.5 usually quoted for
   the alpha relaxation of polymers):
       E(t) = E_g phi(t) + E_r(t) (1 - phi(t)),
   a mixture that is E_g at t = 0, E_r for t >> tau_g, and decreases monotonically in between.
   tau_g(23 C) = tau_g(T_g) / a_T(T_g) with the CONVENTION tau_g(T_g) = 100 s (the structural
   relaxation time commonly associated with the calorimetric T_g; illustrative) and a_T the WLF shift
   of step 5. E_inf is calibrated so that the full curve gives the Gent modulus at 3 s (the glassy term
   is negligible there: tau_g(23 C) <= 2e-5 s for every compound here).
4. That curve, sampled at 20 points per decade from 10^(lg - 6) s to 1e12 s (lg = floor(log10
   tau_g(23 C)): the glassy plateau is in the window), fitted with E_inf and Prony terms, two per
   decade from 10^(lg - 5) to 10^(lg + 4) s (the transition: one per decade leaves a 10-30 % ripple
   where the modulus falls by ~100x within two decades) and one per decade above, up to 1e12 s, by
   non-negative least squares on relative residuals (Lawson-Hanson, scipy.optimize.nnls). The
   fitted E_inf is a few per cent above the Chasset-Thirion E_inf: it holds the (slow) relaxation
   beyond 1e12 s, which the data window does not see. E0 = E_inf + sum E_i is then ~E_g.
5. WLF with the "universal" constants C1 = 17.44, C2 = 51.6 K at Tref = T_g (Williams, Landel & Ferry,
   J. Am. Chem. Soc. 77 (1955) 3701), moved to Tref = 23 C exactly:
   C2' = C2 + (Tref - T_g), C1' = C1 C2 / C2'. sealsim freezes the shift at T <= Tref - C2' =
   T_g - 51.6 K (a_T = infinity: no relaxation progresses, the response is the instantaneous E0 ~ E_g).
6. Glassy linear CTE below T_g: GLASSY_CTE_RATIO = 1/3 of the rubbery one, ASSUMED (no source was
   found for a compound of these classes; the CTE of amorphous polymers is known to drop at T_g).

Run:  python3 materials/derive_illustrative.py --write   (needs numpy, scipy) — rewrites the Prony
tables, WLF constants and fit residuals of the TOML files from COMPOUNDS below (the other numbers and
their sources are in COMPOUNDS too). Without --write it only prints them.
"""
import math
import numpy as np
from scipy.optimize import nnls

M_DEFAULT, TAU0, T_TEST = 0.10, 1e-3, 3.0
E_GLASS_DEFAULT = 2e9          # Pa, illustrative glassy modulus of an amorphous polymer below T_g
TAU_G_AT_TG = 100.0            # s, conventional structural relaxation time at the calorimetric T_g
BETA = 0.4                     # KWW stretching exponent of the glass-rubber transition, assumed
C1G, C2G, TREF = 17.44, 51.6, 296.15
# decades (of 10^floor(log10 tau_g(23 C))) below which the first Prony tau and the first data point
# lie, and above which the Prony terms go from two to one per decade
TAUS_BELOW, DATA_BELOW, DENSE_ABOVE = 5, 6, 4
GLASSY_CTE_RATIO = 1 / 3       # alpha_g / alpha_r, assumed


def gent(shore):
    return 0.0981 * (56 + 7.62336 * shore) / (0.137505 * (254 - 2.54 * shore)) * 1e6


def wlf(tg_c):
    """WLF universal constants moved to Tref = 23 C: (C1', C2')."""
    c2 = C2G + (TREF - (tg_c + 273.15))
    return C1G * C2G / c2, c2


def tau_g_ref(tg_c):
    """tau_g at 23 C: TAU_G_AT_TG / a_T(T_g), log10 a_T(T_g) = -C1'(T_g - Tref)/(C2' + T_g - Tref)."""
    c1, c2 = wlf(tg_c)
    dt = tg_c + 273.15 - TREF
    return TAU_G_AT_TG / 10 ** (-c1 * dt / (c2 + dt))


def curve(t, e_inf, m, e_g, tau_g):
    """E(t) = E_g phi + E_r (1 - phi), phi = exp(-(t/tau_g)^beta), E_r = E_inf [1 + ((t + tau_g)/tau0)^-m]."""
    phi = np.exp(-(t / tau_g) ** BETA)
    e_r = e_inf * (1 + ((t + tau_g) / TAU0) ** -m)
    return e_g * phi + e_r * (1 - phi)


def derive(shore, tg_c, m, e_g):
    e_test = gent(shore)
    tau_g = tau_g_ref(tg_c)
    # E(3 s) is linear in E_inf: E = E_g phi + E_inf (1 + ...) (1 - phi)
    phi3 = math.exp(-(T_TEST / tau_g) ** BETA)
    e_inf = (e_test - e_g * phi3) / ((1 + ((T_TEST + tau_g) / TAU0) ** -m) * (1 - phi3))
    lg = math.floor(math.log10(tau_g))
    t_lo, tau_lo, tau_mid = lg - DATA_BELOW, lg - TAUS_BELOW, lg + DENSE_ABOVE
    t = np.logspace(t_lo, 12, (12 - t_lo) * 20 + 1)
    target = curve(t, e_inf, m, e_g, tau_g)
    # two terms per decade through the transition (one per decade leaves a ripple of 10-30 %
    # where the modulus falls by ~100x in two decades), one per decade on the rubbery side
    taus = np.concatenate([np.logspace(tau_lo, tau_mid, (tau_mid - tau_lo) * 2 + 1),
                           np.logspace(tau_mid + 1, 12, 12 - tau_mid)])
    a = np.hstack([np.ones((len(t), 1)), np.exp(-t[:, None] / taus[None, :])]) / target[:, None]
    sol, _ = nnls(a, np.ones(len(t)), maxiter=20 * a.shape[1])
    rel = np.abs(a @ sol - 1)
    e_inf_ct, e_inf, coef = e_inf, sol[0], sol[1:]
    c1, c2 = wlf(tg_c)
    return dict(e_test=e_test, e_inf=e_inf, e_inf_ct=e_inf_ct, terms=[(c, tau) for c, tau in zip(coef, taus) if c > 0],
                max_rel=rel.max(), rms_rel=math.sqrt((rel ** 2).mean()), c1=c1, c2=c2, tau_g=tau_g,
                t_lo=t_lo, tau_lo=tau_lo, e0=sol.sum(), m=m, e_g=e_g)


HANDBOOK = ("Handbook of Plastics Technologies: The Complete Guide to Properties and Performance "
            "(McGraw-Hill, 2006)")
KOMMLING = ("A. Kömmling, M. Jaunich, D. Wolff, 'Ageing and lifetime prediction of O-ring seals made of "
            "HNBR, EPDM and FKM', Fall Rubber Colloquium (Kautschuk Herbst Kolloquium), Hanover, 2016 "
            "(BAM OPUS4-38480)")
YEAR = 365.25 * 86400
R_GAS = 8.314462618


def rate_to_set(years, set_fraction):
    """The scission rate k [1/s] that reaches a compression set `set_fraction` in `years` with
    the two-network model's CS = 1 - exp(-k t) (balanced crosslinking, docs/model.md 6.5)."""
    return -math.log(1 - set_fraction) / (years * YEAR)


def ten_degree_doubling(tref_c):
    """Ea [J/mol] of the rule 'rates double for 10 K' at tref_c: R ln2 / (1/T - 1/(T + 10))."""
    t = tref_c + 273.15
    return R_GAS * math.log(2) / (1 / t - 1 / (t + 10))


BODE = ("Bode Seal, technical support, '1 PROPERTIES OF ELASTOMER' table "
        "(https://www.bodeseal.com/technical-support/; docs/sources/elastomer-temperatures.md)")
PSP_LIFE = ("Problem Solving Products, 'Seal thermal stability' (pspglobal.com): 'The high-temperature "
            "limit for seal thermal stability is generally considered a 30-50% loss of physical "
            "properties and typically represents a maximum temperature for 1,000 hours continuous "
            "service'")
# T10 - T_g of these derived entries (WLF universal constants, the glass-rubber mixture above):
# 8.1-9.0 K; a calibrated T_g is placed this far below the published low-temperature limit
T10_ABOVE_TG = 8.5
RULE_HOURS = 1000.0


def rate_for_hours(hours, fraction=0.5):
    """k [1/s] whose retained force exp(-k t) reaches `fraction` in `hours` (the two-network
    model's chemical force decay at constant squeeze, docs/model.md 6.5)."""
    return -math.log(fraction) / (hours * 3600.0)


def two_anchor_ea(t1_c, hours1, t2_c, hours2):
    """Ea [J/mol] of the Arrhenius law through two times to the same criterion."""
    t1, t2 = t1_c + 273.15, t2_c + 273.15
    return R_GAS * math.log(hours1 / hours2) / (1 / t1 - 1 / t2)


def t50_hours(years, set_fraction):
    """Hours to 50 % retained force of a ring that reaches `set_fraction` compression set in
    `years` (CS = 1 - exp(-k t) = 1 - F/F0 with balanced crosslinking)."""
    return years * YEAR / 3600.0 * math.log(2) / -math.log(1 - set_fraction)


PSP_RULE = ("the 10 K doubling rule ('chemical reactions typically double with a 10 C increase in "
            "temperature': Problem Solving Products Inc., 'Seal Thermal Stability', pspglobal.com)")
CTE_ASSUMED = ("assumed 160e-6 1/K, of the order of the sourced NBR and EPDM values; no source found for "
               "this polymer; illustrative")

# FKM's Ea: the Arrhenius slope through its two anchors (BAM's 60 C set point, the 200 C rating)
FKM_EA = two_anchor_ea(60.0, t50_hours(40, 0.65), 200.0, RULE_HOURS)
# HNBR's band (docs/model.md 6.5): the low end of NBR's 50-65 kJ/mol in hydraulic fluid (Pazur et
# al. 2012) and the Therban rule, life doubled per +10 K near the 150 C rating
HNBR_EA_LOW = 50e3
THERBAN_EA = ten_degree_doubling(150.0)

# id, name, Shore A grade, T_g [C] with source, linear CTE [1/K] with source, ageing or None; optional
# "m" (Chasset-Thirion exponent, default M_DEFAULT) and "e_g" (glassy modulus [Pa], default
# E_GLASS_DEFAULT) per compound
COMPOUNDS = [
    dict(id="nbr-70", name="NBR (nitrile rubber, medium acrylonitrile), 70 Shore A", shore=70,
         low=-30, rated=100,
         tg=-34, tg_src=f"{HANDBOOK}, Table 4.2: nitrile rubber, medium nitrile, T_g = -34 C",
         cte=165e-6, cte_src="midpoint of the 150-180e-6 1/K given for NBR by NETZSCH (Polymers, "
         "NBR material page, analyzing-testing.netzsch.com); illustrative for a given compound",
         ageing=dict(ea=57.5e3, rate=rate_to_set(15, 0.5), tref=23.0, medium="mineral-oil",
                     prop="tensile elongation of NBR O-rings aged in hydraulic fluid (with hardness, "
                     "compression set and crosslink density)",
                     crit="50 % loss of elongation at break (about 50 % compression set)",
                     src="R.J. Pazur, J.G. Cormier, K. Korhan-Tayma, 'Service life determination of "
                     "nitrile O-rings in hydraulic fluid', ACS Rubber Division 182nd meeting, "
                     "Cincinnati, 2012, paper 8 (abstract read): Ea = 50-65 kJ/mol (midpoint 57.5 "
                     "taken), 20-30 kJ/mol below NBR aged in air (a Sandia study gives 92 kJ/mol on "
                     "elongation in air: 'A critical assessment of the Arrhenius oven-aging "
                     "methodology', 1993, abstract); service life 15 years at 23 C (the abstract "
                     "prints '230C', read as 23 C); k_ref from CS = 1 - exp(-k t) = 0.5 at 15 years "
                     "(elongation criterion taken as a set criterion, an assumption); illustrative",
                     ea_src="Pazur et al. 2012: 50-65 kJ/mol on NBR O-rings in hydraulic fluid "
                     "(midpoint)")),
    dict(id="hnbr-75", name="HNBR (hydrogenated nitrile rubber), 75 Shore A", shore=75,
         low=-30, rated=150,
         tg=-30 - T10_ABOVE_TG, tg_src=f"calibrated: placed {T10_ABOVE_TG:g} K below the -30 C "
         f"standard low-temperature limit of {BODE} so that T10 meets it (the class's calorimetric "
         f"T_g is -30 C: {HANDBOOK}, Table 4.2: hydrogenated nitrile)",
         cte=160e-6, cte_src=CTE_ASSUMED,
         ageing=dict(ea=HNBR_EA_LOW, ea_above=THERBAN_EA, medium="air",
                     rate=rate_for_hours(RULE_HOURS), tref=150.0,
                     prop="the rated-temperature rule (k at 150 C); Ea ASSUMED: a band about the "
                     "rating",
                     crit="50 % retained force",
                     src=f"k at 150 C from 1000 h to 50 % retained force at the rated 150 C ({BODE}; "
                     f"the rule: {PSP_LIFE}). Ea ASSUMED, no HNBR value found: the band "
                     f"{HNBR_EA_LOW / 1e3:g}-{THERBAN_EA / 1e3:.4g} kJ/mol, the low end below the "
                     "rating and the high end above it (the shorter life on both sides, docs/model.md "
                     "6.5). Low end: the lower end of the 50-65 kJ/mol of NBR O-rings in hydraulic "
                     "fluid (Pazur et al. 2012, abstract), HNBR's parent polymer: hydrogenation "
                     "removes the double bonds oxidation attacks, so HNBR is taken to age no faster "
                     "below its rating than NBR relative to its own. High end: Bayer's Therban rule, "
                     "'This service temperature limit can be increased by ca. 10 C being equivalent to "
                     "a doubling of the service life-time' near 150 C (Wrana, Reinartz, Winkelbach, "
                     "Macromol. Mater. Eng. 286 (2001) 657, abstract), R ln2/(1/423.15 - 1/433.15) = "
                     f"{THERBAN_EA / 1e3:.4g} kJ/mol. Not used for the slope: about 5 years to 85 % "
                     f"compression set at 60 C from {KOMMLING} (abstract read), which through the 150 C "
                     "anchor gives 36 kJ/mol (the value used before) and put HNBR below NBR under "
                     "40 C; at 60 C set still holds much physical (viscoelastic) set, and that "
                     "compound ages far faster at 150 C than the chart rating allows; this entry "
                     "lives about 2.9x that extrapolation at 60 C (NOT conservative against that "
                     "one point); illustrative",
                     ea_src="ASSUMED band 50-105.6 kJ/mol: low end NBR's (Pazur et al. 2012), high "
                     "end the Therban +10 C life-doubling rule at 150 C")),
    dict(id="fkm-75", name="FKM (fluoroelastomer), 75 Shore A", shore=75,
         low=-15, rated=200,
         tg=-15 - T10_ABOVE_TG, tg_src=f"calibrated: placed {T10_ABOVE_TG:g} K below the -15 C "
         f"standard low-temperature limit of {BODE} so that T10 meets it (Encyclopaedia Britannica, "
         "'elastomer', gives T_g = -10 C for fluoroelastomer; copolymer/terpolymer grades differ)",
         cte=160e-6, cte_src=CTE_ASSUMED,
         ageing=dict(ea=FKM_EA, medium="air",
                     rate=rate_for_hours(RULE_HOURS), tref=200.0,
                     prop="compression set of O-rings (60 C anchor); the rated-temperature rule "
                     "(200 C anchor)",
                     crit="50 % retained force (65 % compression set converted)",
                     src=f"two anchors: 1000 h to 50 % retained force at the rated 200 C ({BODE}; "
                     f"the rule: {PSP_LIFE}) and about 40 years to 65 % compression set at 60 C "
                     f"from {KOMMLING}, converted with CS = 1 - exp(-k t); Ea is the Arrhenius slope "
                     "through both, within the 47-214 kJ/mol of the European Sealing Association / "
                     "Cetim round robin on compression set (Valve World, August 2023, p. 53; its "
                     "38 kJ/mol on stress relaxation, used before, put 4000 h at 200 C; "
                     "74.9-159.6 kJ/mol on elongation, set and hardness of two ternary FKMs: Lee et "
                     "al., Polymers 14 (2022) 2047, abstract); illustrative",
                     ea_src="two anchors: Kommling et al. 2016 (40 years to 65 % set at 60 C) and "
                     "1000 h at the rated 200 C; inside ESA/Cetim's 47-214 kJ/mol")),
    dict(id="epdm-70", name="EPDM (ethylene propylene diene rubber), 70 Shore A", shore=70,
         low=-50, rated=150,
         tg=-55, tg_src=f"{HANDBOOK}, Table 4.2: EPDM, T_g = -55 C",
         cte=160e-6, cte_src="Wikipedia, 'EPDM rubber', properties table: linear thermal expansion "
         "160 um/(m K) (read from a mirror); illustrative for a given compound",
         ageing=dict(ea=72e3, rate=rate_to_set(64, 0.85), tref=60.0, medium="air",
                     prop="compression set of O-rings aged at 25 % compression (k_ref); tensile "
                     "strength x elongation of EPDM compounds (Ea)",
                     crit="85 % compression set (k_ref); Arrhenius slope of the property (Ea)",
                     src=f"k_ref at 60 C from {KOMMLING} (abstract read): about 64 years to 85 % "
                     "compression set at 60 C, converted with CS = 1 - exp(-k t); Ea = 72 kJ/mol, "
                     "the midpoint of the 68.7 and 75.8 kJ/mol of two EPDM recipes (China "
                     "Rubber/Plastics Technology & Equipment, English edition, January 2026, p. 87, "
                     "Table 7); different studies and properties: illustrative",
                     ea_src="68.7-75.8 kJ/mol on tensile strength x elongation of two EPDM recipes "
                     "(China Rubber/Plastics Technology & Equipment, 2026), midpoint")),
    dict(id="vmq-70", name="VMQ (silicone rubber), 70 Shore A", shore=70,
         low=-55, rated=200,
         tg=-55 - T10_ABOVE_TG, tg_src=f"calibrated: placed {T10_ABOVE_TG:g} K below the -55 C "
         f"low-temperature limit of {BODE} so that T10 meets it. Silicone's calorimetric T_g is "
         f"-127 C ({HANDBOOK}, Table 4.1), but it stiffens long before: 'they do transition from a "
         "soft rubber to a harder rubber around -45 C' on slow cooling (IPC, electronics.org), "
         "crystallising near -100...-80 C on heating and melting near -40 C (Mettler-Toledo, "
         "MatChar HB436); the model has no crystallisation, so this effective glass transition "
         "stands in for it",
         cte=200e-6, cte_src="estimated: an unfilled silicone rubber can exceed 300e-6 1/K and fillers "
         "reduce the CTE by 30-50 % (engineeringniche.com, 'Designing rubber and elastomeric materials "
         "to accommodate thermal expansion'); 200e-6 1/K taken for a filled compound, illustrative",
         ageing=dict(ea=67.7e3, rate=rate_for_hours(RULE_HOURS), tref=200.0,
                     prop="compression set (Ea); the rated-temperature rule (k at 200 C)",
                     crit="50 % retained force",
                     src="Ea = 67.7 kJ/mol on compression set: K. Xiang et al., 'Accelerated thermal "
                     "ageing studies of polydimethylsiloxane (PDMS) rubber', J. Polym. Res. 19 (2012) "
                     f"9869 (abstract); k at 200 C from 1000 h to 50 % retained force at the rated "
                     f"200 C ({BODE}; the rule: {PSP_LIFE}); illustrative",
                     ea_src="Xiang et al. 2012: 67.7 kJ/mol on compression set of PDMS")),
    dict(id="cr-70", name="CR (polychloroprene), 70 Shore A", shore=70,
         low=-40, rated=100,
         tg=-45, tg_src=f"{HANDBOOK}, Table 4.2: polychloroprene, T_g = -45 C",
         cte=160e-6, cte_src=CTE_ASSUMED,
         ageing=dict(ea=80e3, rate=rate_for_hours(RULE_HOURS), tref=100.0,
                     prop="modulus, hardness and elongation (Ea); the rated-temperature rule (k at "
                     "100 C)",
                     crit="50 % retained force",
                     src="Ea = 80 kJ/mol, about the value for the modulus, hardness and elongation "
                     "of neoprenes aged at 70-90 C: R. Bouaziz et al., 'Elastic properties of "
                     "polychloroprene rubbers in tension and compression during ageing', Polymers 12 "
                     f"(2020) 2354 (abstract); k at 100 C from 1000 h to 50 % retained force at the "
                     f"rated 100 C ({BODE}; the rule: {PSP_LIFE}); illustrative",
                     ea_src="Bouaziz et al. 2020: about 80 kJ/mol on modulus, hardness and "
                     "elongation of neoprenes")),
]

# The compounds added in issue 31: k at the rated temperature from the 1000 h rule; Ea a band
# [low, high] about that anchor, the low end below the rating and the high end above it, which
# gives the shorter life on both sides (docs/model.md 6.5). Each band is its class's (or its
# nearest relative's) from a source read; where none was found the band says so (ASSUMED).
EMI = "EMI Seals, '308 Butyl rubber' data sheet (emiseals.com/data-sheet/308-butyl-rubber/)"
PDB = "polymerdatabase.com, 'ACM' (Elastomers; the same text at clwydcompounders.com, 'ACM rubber')"
MOLDED = ("Molded Dimensions 'Chemical resistance properties' chart (the maker's page source, mirrored at "
          "GitHub foresitegroup/moldeddimensions2016, chemical-resistance-properties.php; secondary)")
DANCO = "Danco Industry, 'Chemical' engineering page (dancoindustry.com/engineering/chemical; secondary)"


def rated_ageing(rated_c, low, high, src, ea_src, medium="air"):
    return dict(ea=low, ea_above=high, rate=rate_for_hours(RULE_HOURS), tref=float(rated_c),
                medium=medium,
                prop="the rated-temperature rule (k at the rating); Ea a band about the rating",
                crit="50 % retained force",
                src=f"k at {rated_c} C from 1000 h to 50 % retained force at the rated {rated_c} C "
                    f"(the rule: {PSP_LIFE}); Ea the band {low / 1e3:.4g}-{high / 1e3:.4g} kJ/mol, the "
                    "low end below the rating and the high end above it (the shorter life on both "
                    f"sides, docs/model.md 6.5): {src}; illustrative",
                ea_src=ea_src)


PAZUR_BIIR = ("R.J. Pazur, T. Mengistu, 'Influence of the crosslink structure on the activation energy "
              "calculated under thermo-oxidative conditions', Rubber Chem. Technol. 91 (2018) 205 "
              "(abstract read): six bromobutyl (BIIR) compounds, 'The activation energy for the high "
              "temperature oxidation process is in the range of 107 to 133 kJ/mol' (85-115 C) and 'The "
              "low temperature activation energy is in the range of 55-60 kJ/mol' (23-85 C), on "
              "hardness, mechanical properties and network chain density; bromobutyl stands in for "
              "butyl")
DOLE = ("P. Dole, J. Chauchard, 'Thermal aging of polyethylene-co-methyl acrylate elastomer: activation "
        "energies of physical and physicochemical mechanisms', J. Appl. Polym. Sci. 65 (1997) 2507 "
        "(abstract read): 'Relaxation mechanism has been found to have the lowest activation energy (45 "
        "kJ/mol). Dominant chemical modification has been found to have the highest activation energy "
        "(119 kJ/mol)', relaxation measured as compression set; the ethylene-acrylate elastomer (AEM) "
        "stands in for ACM, the nearest acrylic elastomer with a value found")
FVMQ_EA_SRC = ("ASSUMED, no FVMQ value found: low end VMQ's 67.7 kJ/mol on compression set (K. Xiang et "
               "al., J. Polym. Res. 19 (2012) 9869, abstract), the same siloxane backbone (with it FVMQ "
               "ages 2.6x faster than VMQ at every temperature below 175 C, from its 25 K lower "
               f"rating); high end {PSP_RULE} at 175 C, R ln2/(1/448.15 - 1/458.15)")
FFKM_EA_SRC = ("ASSUMED, no FFKM value found: low end the fkm-75 entry's own slope (two anchors, "
               "Kommling et al. 2016 and the 200 C rating): an FFKM is taken to age no faster below "
               "its rating than the FKM it perfluorinates (the ESA/Cetim round robin's 38 kJ/mol on "
               "stress relaxation of an FKM, used before, put FFKM below FKM under 85 C, which no "
               "source says); high end the highest of the round robin's compression-set energies, "
               "214 kJ/mol (B. Omnes, 'Arrhenius seal life prediction project', Valve World, August "
               "2023, p. 53; 74.9-159.6 kJ/mol for two ternary FKMs, Lee et al., Polymers 14 (2022) "
               "2047, abstract)")


COMPOUNDS += [
    dict(id="iir-70", name="IIR (butyl rubber), 70 Shore A", shore=70, low=-55, rated=105,
         tg=-55 - T10_ABOVE_TG, tg_src=f"calibrated: placed {T10_ABOVE_TG:g} K below the -55 C "
         f"low-temperature limit of {EMI} ('Temperature Range: -55 C to +105 C') so that T10 meets it "
         f"(the class's calorimetric T_g: -66 C, {HANDBOOK}, Table 4.2; butyl's broad, highly damped "
         "transition is not modelled)",
         cte=160e-6, cte_src=CTE_ASSUMED,
         ageing=rated_ageing(105, 55e3, 133e3, PAZUR_BIIR,
                             "Pazur & Mengistu 2018 (bromobutyl): 55-60 kJ/mol at 23-85 C, 107-133 "
                             "at 85-115 C; band 55-133"),
         compat=[("mineral-oil", "X", f"{MOLDED}, row 'Oil and gasoline': Butyl P"),
                 ("water", "A", f"{MOLDED}, row 'Water resistance': Butyl E")]),
    dict(id="fvmq-70", name="FVMQ (fluorosilicone rubber), 70 Shore A", shore=70, low=-55, rated=175,
         tg=-55 - T10_ABOVE_TG, tg_src=f"calibrated: placed {T10_ABOVE_TG:g} K below the -55 C "
         f"low-temperature limit of {BODE} (FVMQ column) so that T10 meets it; like VMQ the effective "
         "glass transition stands in for the stiffening the model does not otherwise have",
         cte=200e-6, cte_src="ASSUMED equal to vmq-70's estimate for a filled silicone (engineeringniche.com, "
         "'Designing rubber and elastomeric materials to accommodate thermal expansion'); no FVMQ "
         "value found; illustrative",
         ageing=rated_ageing(175, 67.7e3, ten_degree_doubling(175.0), FVMQ_EA_SRC,
                             "ASSUMED band 67.7-118 kJ/mol: low end VMQ's (Xiang et al. 2012), high "
                             "end the 10 K doubling rule at 175 C"),
         compat=[]),
    dict(id="ffkm-75", name="FFKM (perfluoroelastomer), 75 Shore A", shore=75, low=-15, rated=260,
         tg=-15 - T10_ABOVE_TG, tg_src=f"calibrated: placed {T10_ABOVE_TG:g} K below the -15 C "
         f"standard low-temperature limit of {BODE} (FFKM column; special grades -35 C) so that T10 "
         "meets it",
         cte=160e-6, cte_src=CTE_ASSUMED,
         ageing=rated_ageing(260, FKM_EA, 214e3, FFKM_EA_SRC,
                             f"ASSUMED band {FKM_EA / 1e3:.3g}-214 kJ/mol: low end the FKM entry's "
                             "slope, high end ESA/Cetim's highest on compression set"),
         compat=[("hot-water", "A", "steam 'Above +200 C (> 14.6 bar) | FFKM': O-Ring Supply Co., "
                  "'Best O-ring material for steam' (secondary); 'FFKM - virtually everything': PTI "
                  "seal chemical compatibility glossary, pti-latam.com (tertiary)")]),
    dict(id="acm-70", name="ACM (polyacrylate rubber), 70 Shore A", shore=70, low=-10, rated=150,
         tg=-10 - T10_ABOVE_TG, tg_src=f"calibrated: placed {T10_ABOVE_TG:g} K below the -10 C of {PDB} "
         "('low temperature applications are usually limited to approximately -10 C'; a distributor "
         "glossary gives -15 C: the higher limit is the conservative one) so that T10 meets it",
         cte=160e-6, cte_src=CTE_ASSUMED,
         ageing=rated_ageing(150, 45e3, 119e3, DOLE,
                             "Dole & Chauchard 1997 (AEM, ACM's nearest relative read): 45 kJ/mol on "
                             "relaxation (compression set), 119 on the dominant chemical change"),
         compat=[("mineral-oil", "A", f"'resistant to heat, hydrocarbon oils and in particular, oil "
                  f"additives': {DANCO}"),
                 ("water", "X", f"'extremely susceptible to hydrolysis, hence their unsuitability for "
                  f"use in aqueous media': {DANCO}"),
                 ("hot-water", "X", f"'unsuitability for use in aqueous media' (hydrolysis): {DANCO}"),
                 ("water-glycol", "X", f"'unsuitability for use in aqueous media' (hydrolysis): "
                  f"{DANCO}")]),
]


def compatibility_block(c, existing):
    """The [material.compatibility] table: kept from the file when it has one (the ratings are
    sourced data edited in the files), else from the compound's `compat` list."""
    if existing and "[material.compatibility]" in existing:
        block = existing.split("[material.compatibility]", 1)[1].split("\n\n", 1)[0]
        return ["", "[material.compatibility]" + block.rstrip("\n")]
    lines = ["", "[material.compatibility]",
             "# A recommended, B limited, X not recommended (docs/model.md §6.8); a class not listed: "
             "not rated"]
    lines += [f'{k} = {{ rating = "{r}", source = "{src}" }}' for k, r, src in c.get("compat", [])]
    return lines


def toml_for(c, existing=None):
    d = derive(c["shore"], c["tg"], c.get("m", M_DEFAULT), c.get("e_g", E_GLASS_DEFAULT))
    glassy_cte = c["cte"] * GLASSY_CTE_RATIO
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
    lines += [f'    {{ modulus = "{m / 1e6:.6g} MPa", tau = "{tau:.6g} s" }},' for m, tau in d["terms"]]
    lines += [
        "]",
        f'glass_transition = "{c["tg"]} C"',
        f'thermal_expansion = "{c["cte"]:.3g} 1/K"',
        f'glassy_thermal_expansion = "{glassy_cte:.3g} 1/K"',
        "",
        "[material.shift]",
        'kind = "wlf"',
        'reference_temperature = "23 C"',
        f"c1 = {d['c1']:.6g}",
        f'c2 = "{d["c2"]:.6g} K"',
    ]
    if c["ageing"]:
        a = c["ageing"]
        lines += ["", "[material.ageing]", f'activation_energy = "{a["ea"] / 1e3:.4g} kJ/mol"']
        if a.get("ea_above"):
            lines.append(f'activation_energy_above = "{a["ea_above"] / 1e3:.4g} kJ/mol"')
        lines += [f'rate = "{a["rate"]:.3e} 1/s"', f'reference_temperature = "{a["tref"]:g} C"',
                  "crosslinking = 1.0",
                  f'property = "{a["prop"]}"', f'criterion = "{a["crit"]}"']
        if a.get("medium"):
            lines.append(f'medium = "{a["medium"]}"')
        lines.append(f'source = "{a["ea_src"]}"')
    lines += compatibility_block(c, existing)
    gent_src = (f"E(3 s, 23 C) = {d['e_test'] / 1e6:.4f} MPa from Gent's relation at {c['shore']} Shore A "
                "(A.N. Gent 1958, 'On the relation between indentation hardness and Young's modulus', "
                "form as commonly quoted; the grade is nominal)")
    prov = {
        "poisson_ratio": "rubber is nearly incompressible; 0.5 as in Persson & Yang 2008, section 3; "
                         "illustrative",
        "long_term_modulus": f"NNLS fit (with the prony terms) to E(t) = E_g phi + E_r (1 - phi), "
                             f"E_r = E_inf [1 + ((t + tau_g)/tau0)^-m] (Chasset-Thirion, capped), "
                             f"phi = exp(-(t/tau_g)^beta); E_inf = {d['e_inf_ct'] / 1e6:.4f} MPa "
                             f"calibrated to {gent_src}; assumed m = {d['m']:g}, tau0 = {TAU0:g} s; "
                             "the fitted value also holds the relaxation beyond 1e12 s; illustrative",
        "prony": f"NNLS fit on relative residuals to that curve on 1e{d['t_lo']} .. 1e12 s at 23 C, "
                 f"tau 1e{d['tau_lo']} .. 1e12 s (two per decade up to 1e{d['tau_lo'] + TAUS_BELOW + DENSE_ABOVE} s, "
                 f"then one): max deviation {100 * d['max_rel']:.2f} %, rms {100 * d['rms_rel']:.2f} %; "
                 f"glass transition: E_g = {d['e_g'] / 1e9:g} GPa (illustrative: amorphous polymers "
                 f"are of the order of 1-3 GPa in the glass), tau_g(23 C) = 100 s/a_T(T_g) = "
                 f"{d['tau_g']:.3g} s (convention: 100 s structural relaxation time at the "
                 f"calorimetric T_g; illustrative), assumed beta = {BETA:g}; E0 = "
                 f"{d['e0'] / 1e9:.4g} GPa; below T_g - 51.6 K the WLF shift is frozen and E0 is the "
                 "response at every time; illustrative",
        "shift": "WLF universal constants C1 = 17.44, C2 = 51.6 K at Tref = T_g (Williams, Landel & "
                 "Ferry, J. Am. Chem. Soc. 77 (1955) 3701) moved exactly to Tref = 23 C: "
                 "C2' = C2 + Tref - T_g, C1' = C1 C2/C2', with T_g below; the constants hold from T_g to about T_g + 50 K (IUPAC Gold Book, WLF equation), beyond that an extrapolation; "
                 "illustrative",
        "glass_transition": c["tg_src"],
        "thermal_expansion": c["cte_src"],
        "glassy_thermal_expansion": f"assumed: one third of the rubbery CTE ({c['cte']:.3g} 1/K), "
                                    "used below T_g; no source found for this compound class "
                                    "(the CTE of amorphous polymers drops at T_g); illustrative",
    }
    if c["ageing"]:
        prov["ageing"] = (c["ageing"]["src"] + "; crosslinking = 1 (balanced: the new network forms "
                          "as fast as the old one breaks, Andrews, Tobolsky & Hanson 1946), assumed")
    elif c.get("no_ageing"):
        prov["ageing"] = c["no_ageing"]
    lines += ["", "[material.provenance]"]
    lines += [f'{k} = "{v}"' for k, v in prov.items()]
    return "\n".join(lines) + "\n", d


if __name__ == "__main__":
    import os
    import sys
    here = os.path.dirname(os.path.abspath(__file__))
    for c in COMPOUNDS:
        path = os.path.join(here, c["id"] + ".toml")
        existing = open(path).read() if os.path.exists(path) else None
        text, d = toml_for(c, existing)
        print(f"{c['id']}: E(3 s) = {d['e_test']/1e6:.4f} MPa, E_inf = {d['e_inf']/1e6:.4f} MPa, "
              f"E0 = {d['e0']/1e9:.4f} GPa, tau_g(23 C) = {d['tau_g']:.3g} s, "
              f"fit max {d['max_rel']:.2e} rms {d['rms_rel']:.2e}, C1' = {d['c1']:.4f}, C2' = {d['c2']:.2f} K")
        if "--write" in sys.argv:
            with open(path, "w") as f:
                f.write(text)
