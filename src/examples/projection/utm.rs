//! Seed 004: latitude and longitude to UTM step by step through Karney's
//! Krüger series, with Snyder's classical series beside it, and its
//! practice.

use super::super::drill::{drill, or_given, BoxDef, Drill, Mistake, Rng, Tolerance};
use super::super::fields::{is_seed, Field, Inputs};
use super::super::Example;
use super::figure::figure_step;
use super::*;
use crate::projection::krueger::{self, Series};
use crate::projection::utm::{self, Hemisphere, FALSE_EASTING, FALSE_NORTHING_SOUTH, K0};
use crate::projection::{dms, snyder};
use crate::solution::{NoteKind, Record, Solution};

pub const EXAMPLE: Example = Example {
    id: "utm",
    title: "Latitude and longitude to UTM",
    source: "Lecture 7: Image processing, UTM",
    summary: "A point's zone, band, easting and northing, scale factor and meridian convergence, step by step through the Krüger series, with the classical series beside it.",
    fields,
    solve,
    answer: &["zone", "easting", "northing"],
    labels: LABELS,
    lab: None,
    practice: drill(Drill::new(generate, boxes, Some(chain), mistakes)),
};

/// The seed's default point: Bangkok (13°45′N, 100°30′E), in the zone the
/// seed names for Thailand.
const DEFAULT_LAT: f64 = 13.75;
const DEFAULT_LON: f64 = 100.5;

fn fields() -> Vec<Field> {
    vec![
        latitude_field(DEFAULT_LAT),
        Field::angle("longitude", "Longitude λ", 180.0, ('E', 'W'), DEFAULT_LON).help(
            "Degrees (100.5) or 100°30'E; west negative or W. Beyond ±180° is refused, not wrapped.",
        ),
        ellipsoid_field(),
        Field::integer("zone", "Force a zone", 0.0)
            .range(0.0, 60.0)
            .help("0 = the standard zone; 1–60 puts the point in that zone instead (to see what happens far from its central meridian)."),
    ]
}

fn rule_text(rule: ZoneRule) -> &'static str {
    match rule {
        ZoneRule::Regular => "regular",
        ZoneRule::Norway => "Norway exception (band V, 3°E–12°E → 32)",
        ZoneRule::Svalbard => "Svalbard exception (band X, 0°–42°E → 31, 33, 35, 37)",
        ZoneRule::Forced => "forced",
    }
}

/// The step that finds the zone, its central meridian, Δλ, the band and
/// the hemisphere.
fn zone_step(lon: f64, u: &utm::Forward) -> Step {
    let regular = (((if lon >= 180.0 { lon - 360.0 } else { lon }) + 180.0) / 6.0).floor() + 1.0;
    let text = match u.rule {
        ZoneRule::Regular => format!(
            "Zones are 6° wide, numbered eastward from 180°. {}",
            if lon >= 180.0 {
                "180° is the same meridian as −180°, so it starts zone 1."
            } else {
                ""
            }
        ),
        ZoneRule::Norway => "The regular rule gives zone 31, but in band V (56°N–64°N) zone 32 is widened to 3°E to cover south-west Norway.".to_string(),
        ZoneRule::Svalbard => format!(
            "The regular rule gives zone {regular}, but in band X (72°N–84°N) between 0° and 42°E only the zones 31, 33, 35 and 37 are used (Svalbard); they are 9° or 12° wide."
        ),
        ZoneRule::Forced => format!(
            "Zone {} is forced; the rules would give zone {}. The transverse Mercator works in any zone, but the farther from the central meridian, the larger the scale error.",
            u.zone, u.standard_zone
        ),
    };
    let floor = Relation::new(if u.rule == ZoneRule::Regular {
        r"\text{zone}"
    } else {
        r"\text{zone}_{\text{regular}}"
    })
    .sym(r"\left\lfloor \frac{\lambda^\circ + 180}{6} \right\rfloor + 1")
    .subst(format!(
        r"\left\lfloor \frac{{{} + 180}}{{6}} \right\rfloor + 1",
        par(fmt_sig(lon, 12))
    ))
    .result(regular.to_string());
    let mut step = Step::new("Zone, central meridian, band and hemisphere", text.trim());
    step = if u.rule == ZoneRule::Regular {
        step.relation(floor.key("zone"))
    } else {
        step.relation(floor).relation(
            Relation::new(r"\text{zone}")
                .key("zone")
                .subst(format!(r"\text{{{}}}", rule_text(u.rule)))
                .result(u.zone.to_string()),
        )
    };
    // Δλ is reduced to [−180°, 180°): say so when it wraps.
    let wrap = u.dlon - (lon - u.central_meridian);
    let wrap = if wrap.abs() < 1e-9 {
        String::new()
    } else {
        format!(" {} 360", if wrap > 0.0 { "+" } else { "-" })
    };
    step.relation(central_meridian_relation(u.zone, u.central_meridian))
        .relation(
            Relation::new(r"\Delta\lambda")
                .key("dlon")
                .sym(r"\lambda - \lambda_0")
                .subst(format!(
                    "{} - {}{wrap}",
                    deg(par(fmt_sig(lon, 12))),
                    deg(par(u.central_meridian.to_string()))
                ))
                .result(deg(fmt_sig(u.dlon, 12))),
        )
        .relation(Relation::new("i").sym(r"\left\lfloor\frac{\varphi^\circ + 80}{8}\right\rfloor"))
        .relation(
            Relation::new(r"\text{band}")
                .key("band")
                .sym(r"\text{CDE}\ldots\text{WX}[i]")
                .result(format!(r"\text{{{}}}", u.band)),
        )
        .relation(
            Relation::new(r"\text{hemisphere}")
                .key("hemisphere")
                .result(format!(r"\text{{{}}}", u.hemisphere.name())),
        )
        .value("zone", f64::from(u.zone))
        .value("central_meridian", u.central_meridian)
        .value("dlon", u.dlon)
}

fn solve(inputs: &Record) -> Result<Solution> {
    let i = Inputs(inputs);
    let (lat, lon) = (i.number("latitude")?, i.number("longitude")?);
    let ell = ellipsoid(&i)?;
    let forced = i.number("zone")?;
    let forced = (forced >= 1.0).then_some(forced as u8);
    let u = utm::forward(&ell, lat, lon, forced)?;
    let series = Series::new(&ell);
    let tm = u.tm;
    let mut s = Solution::new(EXAMPLE.id, EXAMPLE.title, inputs.clone());

    s.step(
        Step::new(
            "The point",
            &format!(
                "Latitude {} and longitude {}; in the formulas the angles are in radians.",
                dms::format(lat, 'N', 'S', 4),
                dms::format(lon, 'E', 'W', 4)
            ),
        )
        .relation(
            Relation::new(r"\varphi")
                .sym(r"\frac{\pi}{180}\,\varphi^\circ")
                .subst(deg(fmt_sig(lat, 12)))
                .result(with_unit(&fmt_sig(lat.to_radians(), 12), "rad")),
        )
        .relation(
            Relation::new(r"\lambda")
                .sym(r"\frac{\pi}{180}\,\lambda^\circ")
                .subst(deg(fmt_sig(lon, 12)))
                .result(with_unit(&fmt_sig(lon.to_radians(), 12), "rad")),
        )
        .value("latitude", lat)
        .value("longitude", lon),
    );
    s.step(ellipsoid_step(&ell));
    s.step(zone_step(lon, &u));
    s.step(coefficient_step(&series, true));
    let (t, sg, tp) = (
        fmt_sig(tm.tau, 14),
        par(fmt_sig(tm.sigma, 14)),
        par(fmt_sig(tm.tau_prime, 14)),
    );
    s.step(
        Step::new(
            "Conformal latitude",
            "The ellipsoid is first mapped conformally onto a sphere: τ = tan φ becomes τ′ = tan χ, computed exactly (not by a series).",
        )
        .relation(
            Relation::new(r"\tau")
                .key("tau")
                .sym(r"\tan\varphi")
                .subst(format!(r"\tan {}", deg(par(fmt_sig(lat, 12)))))
                .result(t.clone()),
        )
        .relation(
            Relation::new(r"\sigma")
                .key("sigma")
                .sym(r"\sinh\!\left(e \,\operatorname{atanh}\frac{e\,\tau}{\sqrt{1+\tau^2}}\right)")
                .result(fmt_sig(tm.sigma, 14)),
        )
        .relation(
            Relation::new(r"\tau'")
                .key("tau_prime")
                .sym(r"\tau\sqrt{1+\sigma^2} - \sigma\sqrt{1+\tau^2}")
                .subst(Form::terms([
                    format!(r"{} \sqrt{{1+{sg}^2}}", par(t.clone())),
                    format!(r"- {sg} \sqrt{{1+{}^2}}", par(t.clone())),
                ]))
                .result(fmt_sig(tm.tau_prime, 14)),
        )
        .relation(Relation::new(r"\chi").result(deg(fmt_sig(tm.tau_prime.atan().to_degrees(), 12))))
        .value("tau", tm.tau)
        .value("sigma", tm.sigma)
        .value("tau_prime", tm.tau_prime),
    );
    let dl = deg(par(fmt_sig(u.dlon, 12)));
    s.step(
        Step::new(
            "Transverse Mercator on the sphere",
            "The Gauss–Schreiber coordinates ξ′ (along the central meridian) and η′ (across it), both in units of the sphere's radius.",
        )
        .relation(
            Relation::new(r"\xi'")
                .key("xi_prime")
                .sym(r"\operatorname{atan2}(\tau', \cos\Delta\lambda)")
                .subst(format!(r"\operatorname{{atan2}}({}, \cos {dl})", fmt_sig(tm.tau_prime, 14)))
                .result(fmt_sig(tm.xi_prime, 14)),
        )
        .relation(
            Relation::new(r"\eta'")
                .key("eta_prime")
                .sym(r"\operatorname{asinh}\frac{\sin\Delta\lambda}{\sqrt{\tau'^2 + \cos^2\Delta\lambda}}")
                .subst(format!(
                    r"\operatorname{{asinh}}\frac{{\sin {dl}}}{{\sqrt{{{tp}^2 + \cos^2 {dl}}}}}"
                ))
                .result(fmt_sig(tm.eta_prime, 14)),
        )
        .value("xi_prime", tm.xi_prime)
        .value("eta_prime", tm.eta_prime),
    );
    s.step(
        Step::new(
            "Krüger's series",
            "From the sphere back to the ellipsoid: six terms of a series in the complex number ζ′ = ξ′ + iη′, written out in real and imaginary parts.",
        )
        .relation(series_relation(
            r"\xi",
            "xi",
            r"\xi' + \sum_{j=1}^{6} \alpha_j \sin 2j\xi' \cosh 2j\eta'",
            tm.xi_prime,
            tm.xi,
            true,
        ))
        .relation(series_relation(
            r"\eta",
            "eta",
            r"\eta' + \sum_{j=1}^{6} \alpha_j \cos 2j\xi' \sinh 2j\eta'",
            tm.eta_prime,
            tm.eta,
            true,
        ))
        .value("xi", tm.xi)
        .value("eta", tm.eta),
    );
    let ka = format!(r"0.9996 \times {}", fixed(series.rectifying_radius, 6));
    s.step(
        Step::new(
            "Easting and northing",
            &format!(
                "Scaled by k₀ = 0.9996 and the rectifying radius; 500 000 m is added so that eastings are positive{}.",
                if u.hemisphere == Hemisphere::South {
                    ", and 10 000 000 m in the southern hemisphere so that northings are too"
                } else {
                    "; north of the equator the northing is y itself"
                }
            ),
        )
        .relation(
            Relation::new("x")
                .key("x")
                .sym(r"k_0 A \eta")
                .subst(format!(r"{ka} \times {}", par(fmt_sig(tm.eta, 14))))
                .result(metres(tm.x)),
        )
        .relation(
            Relation::new("y")
                .key("y")
                .sym(r"k_0 A \xi")
                .subst(format!(r"{ka} \times {}", par(fmt_sig(tm.xi, 14))))
                .result(metres(tm.y)),
        )
        .relation(
            Relation::new("E")
                .key("easting")
                .sym(r"500\,000 + x")
                .subst(format!(r"500\,000 + {}", par(fixed(tm.x, 6))))
                .result(metres(u.easting)),
        )
        .relation(
            Relation::new("N")
                .key("northing")
                .sym("N_0 + y")
                .subst(format!(
                    "{} + {}",
                    fixed(u.hemisphere.false_northing(), 0),
                    par(fixed(tm.y, 6))
                ))
                .result(metres(u.northing)),
        )
        .value("x", tm.x)
        .value("y", tm.y)
        .value("easting", u.easting)
        .value("northing", u.northing),
    );
    s.step(
        Step::new(
            "Meridian convergence and scale factor",
            "From the derivative of the same series: γ is the angle from true north to grid north (clockwise), k how much the map enlarges lengths at the point.",
        )
        .relation(
            Relation::new("p'")
                .sym(r"1 + \sum 2j\alpha_j \cos 2j\xi' \cosh 2j\eta'")
                .result(fmt_sig(tm.p, 14)),
        )
        .relation(
            Relation::new("q'")
                .sym(r"\sum 2j\alpha_j \sin 2j\xi' \sinh 2j\eta'")
                .result(sci(tm.q, 10)),
        )
        .relation(
            Relation::new(r"\gamma")
                .key("convergence")
                .sym(r"\operatorname{atan2}(\tau' \sin\Delta\lambda, \sqrt{1+\tau'^2}\cos\Delta\lambda) + \operatorname{atan2}(q', p')")
                .subst(format!(
                    r"{} + {}\,{{}}^\circ",
                    deg(fmt_sig(tm.gamma_sphere.to_degrees(), 12)),
                    par(sci(tm.gamma_series.to_degrees(), 10))
                ))
                .result(deg(fmt_sig(tm.gamma.to_degrees(), 12))),
        )
        .relation(
            Relation::new("k")
                .key("scale_factor")
                .sym(r"k_0 \frac{\sqrt{1-e^2\sin^2\varphi}\,\sqrt{1+\tau^2}}{\sqrt{\tau'^2 + \cos^2\Delta\lambda}}\cdot\frac{A}{a}\sqrt{p'^2+q'^2}")
                .subst(format!(
                    r"0.9996 \times {} \times {}",
                    fmt_sig(tm.k_sphere, 14),
                    fmt_sig(tm.k_series, 14)
                ))
                .result(fmt_sig(tm.k, 14)),
        )
        .value("scale_factor", tm.k)
        .value("convergence", tm.gamma.to_degrees()),
    );

    // the classical series beside it
    let c = snyder::forward(&ell, K0, lat, u.dlon);
    let ce = utm::FALSE_EASTING + c.x;
    let cn = u.hemisphere.false_northing() + c.y;
    let cd = (c.x - tm.x).hypot(c.y - tm.y);
    s.step(
        Step::new(
            "The classical series, for comparison",
            "Snyder's power series in A = Δλ·cos φ (Map Projections — A Working Manual, 1987, eqs. 8-9, 8-10), as many textbooks print it. Near the central meridian it agrees to a millimetre; its error grows quickly with the distance from it.",
        )
        .relation(
            Relation::new("N")
                .sym(r"\frac{a}{\sqrt{1-e^2\sin^2\varphi}}")
                .result(with_unit(&fixed(c.big_n, 4), "m")),
        )
        .relation(Relation::new("T").sym(r"\tan^2\varphi").result(fmt_sig(c.t, 12)))
        .relation(Relation::new("C").sym(r"e'^2\cos^2\varphi").result(fmt_sig(c.c, 12)))
        .relation(Relation::new("A").sym(r"\Delta\lambda\cos\varphi").result(fmt_sig(c.a, 12)))
        .relation(Relation::new("M").result(with_unit(&fixed(c.m, 6), "m")))
        .relation(Relation::new("c_3").sym(r"\frac{1-T+C}{6}"))
        .relation(Relation::new("c_5").sym(r"\frac{5-18T+T^2+72C-58e'^2}{120}"))
        .relation(Relation::new("c_4").sym(r"\frac{5-T+9C+4C^2}{24}"))
        .relation(Relation::new("c_6").sym(r"\frac{61-58T+T^2+600C-330e'^2}{720}"))
        .relation(
            Relation::new("x")
                .sym(r"k_0 N\,(A + c_3 A^3 + c_5 A^5)")
                .result(metres(c.x)),
        )
        .relation(
            Relation::new("y")
                .sym(r"k_0\,\bigl(M + N\tan\varphi\,(\tfrac{A^2}{2} + c_4 A^4 + c_6 A^6)\bigr)")
                .result(metres(c.y)),
        )
        .relation(
            Relation::new(r"\text{distance from the exact point}")
                .key("classical_difference_m")
                .result(with_unit(&sci(cd, 4), "m")),
        )
        .value("classical_easting", ce)
        .value("classical_northing", cn)
        .value("classical_difference_m", cd),
    );
    s.step(figure_step(&ell, lat, &u)?);

    s.result = Record::new()
        .with("zone", f64::from(u.zone))
        .with("band", u.band.to_string().as_str())
        .with("hemisphere", u.hemisphere.name())
        .with("central_meridian", u.central_meridian)
        .with("easting", u.easting)
        .with("northing", u.northing)
        .with("scale_factor", tm.k)
        .with("convergence", tm.gamma.to_degrees())
        .with(
            "utm_text",
            format!(
                "{}{} {} m E, {} m N",
                u.zone,
                u.band,
                plain(u.easting, 3),
                plain(u.northing, 3)
            )
            .as_str(),
        )
        .with("latitude_dms", dms::format(lat, 'N', 'S', 4).as_str())
        .with("longitude_dms", dms::format(lon, 'E', 'W', 4).as_str())
        .with("standard_zone", f64::from(u.standard_zone))
        .with("zone_rule", rule_text(u.rule))
        .with("in_legal_range", u.legal)
        .with("classical_easting", ce)
        .with("classical_northing", cn)
        .with("classical_difference_m", cd);

    if !u.legal {
        s.note(
            NoteKind::Warning,
            format!(
                "E = {} m, N = {} m is outside the legal UTM range (E 100 000–900 000 m; N 0–9 500 000 m north, 1 000 000–10 000 000 m south). The numbers are still the exact transverse Mercator, but no UTM map sheet holds them{}.",
                plain(u.easting, 3),
                plain(u.northing, 3),
                if u.rule == ZoneRule::Forced {
                    format!("; the point's own zone is {}", u.standard_zone)
                } else {
                    String::new()
                }
            ),
        );
    }
    if u.dlon.abs() > 3.0 + 1e-12 && u.rule != ZoneRule::Svalbard {
        s.note(
            NoteKind::Warning,
            format!(
                "The point is {}° from the central meridian, outside the 6° zone: the scale factor is {} ({:+.0} ppm), and the classical series is {} m off here.",
                fmt_sig(u.dlon.abs(), 8),
                fmt_sig(tm.k, 10),
                (tm.k - 1.0) * 1e6,
                fmt_sig(cd, 3)
            ),
        );
    }
    s.note(
        NoteKind::Convention,
        "Latitude 0 counts as north (band N, false northing 0). Longitudes beyond ±180° are refused, not wrapped; 180° and −180° are the same meridian and both lie in zone 1, as in GeographicLib.",
    );
    if is_seed(&fields(), inputs) {
        s.textbook = Some(Record::new().with("zone", 47.0));
        s.note(
            NoteKind::Convention,
            "The lecture gives no coordinates, only \"Thailand: Zone 47\"; this default point is Bangkok (13°45′N, 100°30′E), which is indeed in zone 47. Eastern Thailand (east of 102°E) is in zone 48: see the example \"Lecture 7's UTM facts, checked\".",
        );
    }
    Ok(s)
}

// ---------------------------------------------------------------------------
// Practice: the forward projection as the steps show it, box by box.

const METRES: Tolerance = Tolerance::abs(0.01);

fn generate(rng: &mut Rng) -> Record {
    let (lat, lon) = draw_point(rng);
    Record::new()
        .with("latitude", lat)
        .with("longitude", lon)
        .with("ellipsoid", "wgs84")
}

fn boxes(_: &Record) -> Vec<BoxDef> {
    vec![
        BoxDef::new("zone", "Zone", None, WHOLE)
            .nudge("⌊(λ + 180°) / 6°⌋ + 1 — but check the exceptions: zone 32 in south-west Norway (56°–64°N, 3°–12°E), zones 31, 33, 35, 37 on Svalbard (72°–84°N)."),
        BoxDef::new("central_meridian", "Central meridian λ₀", Some("°"), WHOLE)
            .nudge("The middle of the zone: 6·zone − 183°."),
        BoxDef::new("dlon", "Δλ = λ − λ₀", Some("°"), DEGREES)
            .nudge("How far east (+) or west (−) of the central meridian the point is, in degrees.")
            .sign_flip(EAST_WEST),
        BoxDef::new("tau_prime", "τ′ = tan χ (conformal latitude)", None, RATIO)
            .nudge("τ = tan φ, σ = sinh(e·atanh(e·τ/√(1 + τ²))), τ′ = τ√(1 + σ²) − σ√(1 + τ²)."),
        BoxDef::new("xi_prime", "ξ′ (on the sphere)", None, RATIO)
            .nudge("ξ′ = atan2(τ′, cos Δλ), with Δλ in radians."),
        BoxDef::new("eta_prime", "η′ (on the sphere)", None, RATIO)
            .nudge("η′ = asinh(sin Δλ / √(τ′² + cos² Δλ)), with Δλ in radians."),
        BoxDef::new("xi", "ξ (Krüger series)", None, RATIO)
            .nudge("ξ = ξ′ + Σ αⱼ sin 2jξ′ cosh 2jη′ (j = 1 … 6)."),
        BoxDef::new("eta", "η (Krüger series)", None, RATIO)
            .nudge("η = η′ + Σ αⱼ cos 2jξ′ sinh 2jη′."),
        BoxDef::new("easting", "Easting E", Some("m"), METRES)
            .nudge("E = 500 000 m + k₀·A·η, with k₀ = 0.9996 and A the rectifying radius."),
        BoxDef::new("northing", "Northing N", Some("m"), METRES)
            .nudge("N = k₀·A·ξ, plus 10 000 000 m south of the equator (and only there)."),
        BoxDef::new("scale_factor", "Point scale factor k", None, SCALE)
            .nudge("k = k₀·k′·k″: the sphere's factor times the series' factor."),
        BoxDef::new("convergence", "Meridian convergence γ", Some("°"), CONVERGENCE)
            .nudge("γ = γ′ + γ″: atan2(sin Δλ·τ′, cos Δλ·√(1 + τ′²)) plus the series' part atan2(q′, p′); in degrees.")
            .sign_flip(CONVERGENCE_FLIP),
    ]
}

/// The boxes from the student's earlier answers: the stages of
/// [`krueger::forward`], each replaced by what was given.
fn chain(i: &Record, g: &Record) -> Result<Record> {
    let ell = ellipsoid(&Inputs(i))?;
    let s = Series::new(&ell);
    let (lat, lon) = (n(i, "latitude"), n(i, "longitude"));
    let zone = or_given(g, "zone", f64::from(utm::standard_zone(lat, lon).0));
    let cm = or_given(g, "central_meridian", 6.0 * zone - 183.0);
    let dlon = or_given(g, "dlon", utm::lon_diff(lon, cm));
    let (phi, lam) = (lat.to_radians(), dlon.to_radians());
    let taup = or_given(g, "tau_prime", krueger::tau_prime(phi.tan(), s.e));
    let (xip, etap) = krueger::sphere_forward(taup, lam);
    let xip = or_given(g, "xi_prime", xip);
    let etap = or_given(g, "eta_prime", etap);
    let (a, b, p1, q) = krueger::sums(&s.alpha, xip, etap);
    let xi = or_given(g, "xi", xip + a);
    let eta = or_given(g, "eta", etap + b);
    let false_northing = false_northing_at(lat);
    let p = 1.0 + p1;
    let gamma = krueger::sphere_convergence(taup, lam) + q.atan2(p);
    let k =
        K0 * krueger::sphere_scale(s.e2, phi, taup, lam) * krueger::series_scale(&s, ell.a, p, q);
    Ok(Record::new()
        .with("zone", zone)
        .with("central_meridian", cm)
        .with("dlon", dlon)
        .with("tau_prime", taup)
        .with("xi_prime", xip)
        .with("eta_prime", etap)
        .with("xi", xi)
        .with("eta", eta)
        .with(
            "easting",
            or_given(g, "easting", FALSE_EASTING + K0 * s.rectifying_radius * eta),
        )
        .with(
            "northing",
            or_given(
                g,
                "northing",
                false_northing + K0 * s.rectifying_radius * xi,
            ),
        )
        .with("scale_factor", or_given(g, "scale_factor", k))
        .with("convergence", gamma.to_degrees()))
}

fn mistakes(i: &Record) -> Result<Vec<Mistake>> {
    let ell = ellipsoid(&Inputs(i))?;
    let (lat, lon) = (n(i, "latitude"), n(i, "longitude"));
    let exact = chain(i, &Record::new())?;
    let v = |k: &str| exact.number(k).unwrap_or(f64::NAN);
    let with =
        |g: Record, k: &str| -> Result<f64> { Ok(chain(i, &g)?.number(k).unwrap_or(f64::NAN)) };
    let (zone, rule) = utm::standard_zone(lat, lon);
    let zone = f64::from(zone);
    let cm = v("central_meridian");
    let regular = |l: f64| (((l + 180.0) / 6.0).floor() + 1.0).clamp(1.0, 60.0);
    const SWAP: &str =
        "φ is the latitude (north–south), λ the longitude (east–west): the zone comes from λ.";
    const RULE: &str = "South-west Norway (56°–64°N, 3°–12°E) is all zone 32; on Svalbard (72°–84°N, 0°–42°E) only zones 31, 33, 35 and 37 are used.";
    const OFF: &str =
        "Zone z spans 6z − 186° to 6z − 180°: that meridian belongs to the next zone.";
    const RAD: &str = "Degrees and radians mixed: trigonometric functions need Δλ in radians, the box asks for degrees.";
    const FE: &str = "The false easting: E = 500 000 m + x, so that eastings are never negative.";
    const K0_: &str = "k₀ = 0.9996 scales the whole projection: x = k₀·A·η, y = k₀·A·ξ.";
    let mut out = vec![Mistake::new(
        "zone",
        "latitude and longitude swapped",
        SWAP,
        regular(lat),
    )];
    out.extend(meridian_mistakes(zone, cm, OFF));
    out.extend([
        Mistake::new("dlon", "degrees vs radians", RAD, v("dlon").to_radians()),
        Mistake::new(
            "dlon",
            "6·zone − 180 without the −3",
            EDGE,
            lon - (6.0 * zone - 180.0),
        ),
        Mistake::new(
            "tau_prime",
            "conformal latitude skipped",
            "τ′ is tan of the conformal latitude χ, not tan φ: apply the σ correction.",
            lat.to_radians().tan(),
        ),
    ]);
    if rule != ZoneRule::Regular {
        out.insert(
            0,
            Mistake::new(
                "zone",
                "Norway/Svalbard exception missed",
                RULE,
                regular(lon),
            ),
        );
    }
    // Δλ in degrees fed to sin and cos as if radians.
    let in_degrees = Record::new().with("dlon", v("dlon").to_degrees());
    for key in ["xi_prime", "eta_prime", "easting", "northing"] {
        out.push(Mistake::new(
            key,
            "degrees vs radians",
            RAD,
            with(in_degrees.clone(), key)?,
        ));
    }
    let edge = Record::new().with("central_meridian", 6.0 * zone - 180.0);
    out.push(Mistake::new(
        "easting",
        "6·zone − 180 without the −3",
        EDGE,
        with(edge, "easting")?,
    ));
    for d in [-6.0, 6.0] {
        let g = Record::new().with("central_meridian", cm + d);
        out.push(Mistake::new(
            "easting",
            "zone off by one",
            OFF,
            with(g, "easting")?,
        ));
    }
    let a = Series::new(&ell).rectifying_radius;
    let (xi, eta) = (v("xi"), v("eta"));
    let false_northing = false_northing_at(lat);
    out.extend([
        Mistake::new("easting", "false easting forgotten", FE, K0 * a * eta),
        Mistake::new(
            "easting",
            "k₀ = 0.9996 forgotten",
            K0_,
            FALSE_EASTING + a * eta,
        ),
        Mistake::new(
            "northing",
            "k₀ = 0.9996 forgotten",
            K0_,
            false_northing + a * xi,
        ),
        Mistake::new(
            "scale_factor",
            "k₀ = 0.9996 forgotten",
            K0_,
            v("scale_factor") / K0,
        ),
        Mistake::new(
            "convergence",
            "degrees vs radians",
            "That is γ in radians; the box asks for degrees (× 180/π).",
            v("convergence").to_radians(),
        ),
    ]);
    out.push(if lat >= 0.0 {
        Mistake::new(
            "northing",
            "false northing applied in the north",
            "The 10 000 000 m false northing is for the southern hemisphere only.",
            v("northing") + FALSE_NORTHING_SOUTH,
        )
    } else {
        Mistake::new(
            "northing",
            "false northing forgotten",
            "South of the equator N = 10 000 000 m + k₀·A·ξ (ξ is negative there).",
            v("northing") - FALSE_NORTHING_SOUTH,
        )
    });
    // The whole projection with φ and λ swapped, where that is a UTM point.
    if let Ok(f) = utm::forward(&ell, lon, lat, None) {
        out.push(Mistake::new(
            "easting",
            "latitude and longitude swapped",
            SWAP,
            f.easting,
        ));
        out.push(Mistake::new(
            "northing",
            "latitude and longitude swapped",
            SWAP,
            f.northing,
        ));
    }
    Ok(out)
}
