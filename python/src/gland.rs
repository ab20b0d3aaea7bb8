//! `sealsim.gland`: the recommended gland of an AS568 ring for a service, its ISO 286 fits and
//! tolerance stack-up, and the runnable scenario — `sealsim gland` through
//! [`sealsim::workflow::gland`].

use super::fit::{positive, temperature};
use super::{ScenarioError, blocking, guarded, internal};
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use sealsim::gland::GlandKind;
use sealsim::units::Dimension;
use sealsim::workflow::gland::{GlandError, GlandRequest, design};

/// `sealsim gland`: (the stack-up JSON text of `--json`, the scenario's TOML of `-o`).
#[pyfunction]
#[pyo3(signature = (size, service, dynamic = false, pressure = None, backup_rings = 0,
    bore = None, rod = None, fit = "H8/f7", temperature = None, pressure_difference = None,
    material = "nbr-70", housing = "steel"))]
#[allow(
    clippy::too_many_arguments,
    reason = "the keyword arguments of sealsim.gland"
)]
fn _gland(
    py: Python<'_>,
    size: String,
    service: &str,
    dynamic: bool,
    pressure: Option<&str>,
    backup_rings: u8,
    bore: Option<Bound<'_, PyAny>>,
    rod: Option<Bound<'_, PyAny>>,
    fit: &str,
    temperature: Option<(Bound<'_, PyAny>, Bound<'_, PyAny>)>,
    pressure_difference: Option<Bound<'_, PyAny>>,
    material: &str,
    housing: &str,
) -> PyResult<(String, String)> {
    // the arguments' parsing on the calling thread, the design on the worker
    guarded(|| {
        let kind = match service {
            "face" => GlandKind::Face,
            "piston" => GlandKind::Piston,
            "rod" => GlandKind::Rod,
            other => {
                return Err(PyValueError::new_err(format!(
                    "service \"{other}\": one of \"face\", \"piston\", \"rod\""
                )));
            }
        };
        let bad = |m: &str| Err(PyValueError::new_err(m.to_owned()));
        let pressure_outside = match (pressure, kind) {
            (None, _) => false,
            (Some(_), GlandKind::Piston | GlandKind::Rod) => {
                return bad(
                    "pressure=\"inside\"|\"outside\" is for face glands: a piston or rod \
                            gland seals on either side; drop pressure",
                );
            }
            (Some("inside"), _) => false,
            (Some("outside"), _) => true,
            (Some(other), _) => {
                return Err(PyValueError::new_err(format!(
                    "pressure \"{other}\": \"inside\" or \"outside\""
                )));
            }
        };
        if kind == GlandKind::Face && dynamic {
            return bad(
                "dynamic=True is for piston and rod glands (the tables have no dynamic face \
                        gland)",
            );
        }
        if backup_rings > 2 {
            return bad("backup_rings: 0, 1 or 2");
        }
        let seat = match (&bore, &rod, kind) {
            (Some(_), _, GlandKind::Face | GlandKind::Rod) => {
                return bad("bore= is the bore of a piston gland; a rod gland takes rod=");
            }
            (_, Some(_), GlandKind::Face | GlandKind::Piston) => {
                return bad("rod= is the rod of a rod gland; a piston gland takes bore=");
            }
            (Some(b), _, _) => positive(Some(b), "bore", Dimension::LENGTH)?,
            (_, Some(r), _) => positive(Some(r), "rod", Dimension::LENGTH)?,
            _ => None,
        };
        let temperatures = match &temperature {
            Some((lo, hi)) => {
                let kelvin = |t| {
                    self::temperature(Some(t), "temperature")?
                        .ok_or_else(|| internal("a temperature went missing"))
                };
                let (lo, hi) = (kelvin(lo)?, kelvin(hi)?);
                if lo > hi {
                    return bad("temperature=(min, max): min is above max");
                }
                Some((lo, hi))
            }
            None => None,
        };
        // the value, and its text as typed for the scenario (a float: in Pa)
        let pressure_difference = match &pressure_difference {
            Some(p) => positive(Some(p), "pressure_difference", Dimension::PRESSURE)?.map(|v| {
                let text = p
                    .extract::<String>()
                    .unwrap_or_else(|_| format!("{v:e} Pa"));
                (v, text)
            }),
            None => None,
        };
        let request = GlandRequest {
            size,
            kind,
            dynamic,
            pressure_outside,
            backup_rings,
            seat,
            fit: fit.to_owned(),
            temperatures,
            pressure_difference,
            material: material.to_owned(),
            housing: housing.to_owned(),
        };
        blocking(py, move || {
            let designed = design(&request).map_err(|e| match e {
                GlandError::Input(m) => ScenarioError::new_err(m),
                GlandError::Internal(m) => internal(m),
            })?;
            let json =
                sealsim::report::gland::json(&designed.design, &designed.stack, &designed.context)
                    .map_err(internal)?;
            Ok((json, designed.scenario))
        })?
    })
}

pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_function(wrap_pyfunction!(_gland, m)?)?;
    Ok(())
}
