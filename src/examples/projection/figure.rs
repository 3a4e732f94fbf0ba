//! The data of the map projection figure (`www/figures/projection.js`):
//! the zone's graticule on the map, the scale factor along the point's
//! parallel and the classical series' error, all from the core functions.

use crate::error::Result;
use crate::projection::krueger;
use crate::projection::utm::{self, K0};
use crate::projection::{snyder, Ellipsoid};
use crate::solution::{steps_wanted, Step, Value};

/// The figure's data: the zone's graticule on the map, k across the zone,
/// and the classical series' error against the distance from the central
/// meridian, all from the core functions.
pub(super) fn figure_step(ell: &Ellipsoid, lat: f64, u: &utm::Forward) -> Result<Step> {
    if !steps_wanted() {
        // a sweep's series (no steps): nothing else reads the figure's data,
        // and it cannot fail once `u` was projected (latitudes within the
        // UTM range, offsets under 41° from the central meridian)
        return Ok(Step::new("The zone on the map", ""));
    }
    let fnorth = u.hemisphere.false_northing();
    let span = (u.dlon.abs().ceil()).max(3.0);
    let lon_step = if span <= 6.0 { 1.0 } else { 5.0 };
    let lat_lo = (lat - 6.0).max(utm::LAT_MIN).floor();
    let lat_hi = (lat + 6.0).min(utm::LAT_MAX).ceil();
    let en = |la: f64, dl: f64| -> Result<Vec<f64>> {
        let f = krueger::forward(ell, K0, la, dl)?;
        Ok(vec![
            (utm::FALSE_EASTING + f.x) / 1000.0,
            (fnorth + f.y) / 1000.0,
        ])
    };
    // the central meridian, the zone's edges (±3°), the ends, and the
    // whole (span ≤ 6°) or round-5° longitudes between
    let mut offsets = vec![-span, -3.0, 0.0, 3.0, span];
    offsets.dedup_by(|a, b| (*a - *b).abs() < 1e-9);
    let first = ((u.central_meridian - span) / lon_step).ceil() as i32;
    let last = ((u.central_meridian + span) / lon_step).floor() as i32;
    for i in first..=last {
        let d = f64::from(i) * lon_step - u.central_meridian;
        // a round meridian close to one already drawn would only crowd it
        if offsets.iter().all(|o| (o - d).abs() >= lon_step / 2.0) {
            offsets.push(d);
        }
    }
    offsets.sort_by(f64::total_cmp);
    let mut meridians = Vec::new();
    let mut m_lons = Vec::new();
    for d in offsets {
        let mut line = Vec::new();
        let mut la = lat_lo;
        while la <= lat_hi + 1e-9 {
            line.push(en(la, d)?);
            la += 0.25;
        }
        meridians.push(Value::matrix(&line));
        m_lons.push(u.central_meridian + d);
    }
    let mut parallels = Vec::new();
    let mut p_lats = Vec::new();
    let lat_step = if lat_hi - lat_lo > 8.0 { 2.0 } else { 1.0 };
    let mut la = lat_lo;
    while la <= lat_hi + 1e-9 {
        let mut line = Vec::new();
        let mut dl = -span;
        while dl <= span + 1e-9 {
            line.push(en(la, dl)?);
            dl += span / 40.0;
        }
        parallels.push(Value::matrix(&line));
        p_lats.push(la);
        la += lat_step;
    }
    // k across the zone along the point's parallel
    let reach = (u.dlon.abs() + 0.5).max(3.5);
    let mut k_profile = Vec::new();
    for i in 0..=140 {
        let dl = -reach + 2.0 * reach * i as f64 / 140.0;
        let f = krueger::forward(ell, K0, lat, dl)?;
        k_profile.push(vec![dl, f.x / 1000.0, f.k]);
    }
    // classical − exact along the point's parallel
    let far = (u.dlon.abs() + 1.0).clamp(15.0, utm::MAX_FORCED_OFFSET_DEG);
    let mut diff = Vec::new();
    let mut dl = 0.25;
    while dl <= far + 1e-9 {
        let f = krueger::forward(ell, K0, lat, dl)?;
        let c = snyder::forward(ell, K0, lat, dl);
        diff.push(vec![dl, f.x / 1000.0, (c.x - f.x).hypot(c.y - f.y)]);
        dl += 0.25;
    }
    Ok(Step::new(
        "The zone on the map",
        "The figure draws the zone's meridians and parallels as they land on the map, the scale factor along the point's parallel, and how far the classical series strays from the exact one.",
    )
    .value("meridians", Value::List(meridians))
    .value("meridian_longitudes", Value::numbers(&m_lons))
    .value("map_central_meridian", u.central_meridian)
    .value("parallels", Value::List(parallels))
    .value("parallel_latitudes", Value::numbers(&p_lats))
    .value("point", Value::numbers(&[u.easting / 1000.0, u.northing / 1000.0]))
    .value("point_dlon", u.dlon)
    .value("zone_edges", Value::numbers(&[-3.0, 3.0]))
    .value("equator_northing_km", fnorth / 1000.0)
    .value("k_profile", Value::matrix(&k_profile))
    .value("difference_profile", Value::matrix(&diff)))
}
