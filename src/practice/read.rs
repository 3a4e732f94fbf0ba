//! Reading a student's answer box: a number (decimal point or comma,
//! scientific notation, a fraction) and an optional unit, with the
//! precision the text carries. A text that cannot be read is never a wrong
//! answer: it is reported as unreadable, with what could not be read.

/// What an answer text was read as.
#[derive(Debug, Clone, PartialEq)]
pub struct Reading {
    /// The number as typed, before any unit conversion.
    pub number: f64,
    /// Half a unit of the last digit typed (0 for a fraction: exact).
    pub half_ulp: f64,
    /// The unit typed after the number, if any (normalised: "mm", "°" …).
    pub unit: Option<&'static str>,
}

/// A unit a student may type, its dimension and its size in the
/// dimension's base unit (mm, px, degree, grey value).
struct UnitDef {
    names: &'static [&'static str],
    canonical: &'static str,
    dimension: &'static str,
    scale: f64,
}

const UNITS: &[UnitDef] = &[
    UnitDef {
        names: &[
            "mm",
            "millimetre",
            "millimetres",
            "millimeter",
            "millimeters",
        ],
        canonical: "mm",
        dimension: "length",
        scale: 1.0,
    },
    UnitDef {
        names: &[
            "cm",
            "centimetre",
            "centimetres",
            "centimeter",
            "centimeters",
        ],
        canonical: "cm",
        dimension: "length",
        scale: 10.0,
    },
    UnitDef {
        names: &["m", "metre", "metres", "meter", "meters"],
        canonical: "m",
        dimension: "length",
        scale: 1000.0,
    },
    UnitDef {
        names: &["km", "kilometre", "kilometres", "kilometer", "kilometers"],
        canonical: "km",
        dimension: "length",
        scale: 1.0e6,
    },
    UnitDef {
        names: &["µm", "μm", "um", "micron", "microns"],
        canonical: "µm",
        dimension: "length",
        scale: 0.001,
    },
    UnitDef {
        names: &["px", "pixel", "pixels", "pel"],
        canonical: "px",
        dimension: "pixel",
        scale: 1.0,
    },
    UnitDef {
        names: &["°", "deg", "degree", "degrees"],
        canonical: "°",
        dimension: "angle",
        scale: 1.0,
    },
    UnitDef {
        names: &["rad", "radian", "radians"],
        canonical: "rad",
        dimension: "angle",
        scale: 180.0 / std::f64::consts::PI,
    },
    UnitDef {
        names: &["ppm", "mm/km"],
        canonical: "ppm",
        dimension: "ratio",
        scale: 1.0,
    },
    UnitDef {
        names: &[
            "gv",
            "grey values",
            "grey value",
            "gray values",
            "gray value",
        ],
        canonical: "grey values",
        dimension: "grey",
        scale: 1.0,
    },
];

fn unit_def(name: &str) -> Option<&'static UnitDef> {
    let lower = name.trim().to_lowercase();
    UNITS.iter().find(|u| u.names.contains(&lower.as_str()))
}

/// How a typed unit relates to the unit of the box.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum UnitCheck {
    /// No unit typed: the box's own unit is meant.
    Omitted,
    /// The box's unit, or one of the same dimension (converted by `factor`).
    Fits { factor: f64 },
    /// A unit of another dimension (pixels typed in a millimetre box).
    Wrong,
}

/// Compares the unit typed with the box's unit.
pub fn check_unit(typed: Option<&str>, expected: Option<&str>) -> UnitCheck {
    let Some(typed) = typed else {
        return UnitCheck::Omitted;
    };
    let (Some(t), Some(e)) = (unit_def(typed), expected.and_then(unit_def)) else {
        return UnitCheck::Wrong;
    };
    if t.dimension == e.dimension {
        UnitCheck::Fits {
            factor: t.scale / e.scale,
        }
    } else {
        UnitCheck::Wrong
    }
}

/// Reads an answer text. `Ok(None)` for an empty box; `Err` says what
/// could not be read.
pub fn read(text: &str) -> Result<Option<Reading>, String> {
    let t: String = text
        .trim()
        .chars()
        .map(|ch| match ch {
            '\u{2212}' | '\u{2013}' => '-',
            '\u{00a0}' | '\u{202f}' | '\u{2009}' => ' ',
            '\u{00d7}' | '\u{22c5}' | '\u{00b7}' => '*',
            c => c,
        })
        .collect();
    if t.is_empty() {
        return Ok(None);
    }
    // Split the number part from a trailing unit.
    let num_end = t
        .char_indices()
        .find(|&(i, ch)| {
            !(ch.is_ascii_digit()
                || matches!(ch, '.' | ',' | '+' | '-' | '/' | '*' | '^' | ' ')
                || ((ch == 'e' || ch == 'E') && next_is_exponent(&t[i + ch.len_utf8()..])))
        })
        .map_or(t.len(), |(i, _)| i);
    let (num_text, unit_text) = t.split_at(num_end);
    let num_text = num_text.trim();
    let unit_text = unit_text.trim();
    let unit = if unit_text.is_empty() {
        None
    } else {
        match unit_def(unit_text) {
            Some(u) => Some(u.canonical),
            None => {
                return Err(format!(
                "\"{unit_text}\" is not a unit this box knows (try mm, cm, m, km, px, °, rad, ppm)"
            ))
            }
        }
    };
    if num_text.is_empty() {
        return Err("there is no number in it".to_string());
    }
    if num_text.contains(' ') {
        return Err(format!(
            "\"{num_text}\" has a space inside the number; write it without spaces"
        ));
    }
    let (number, half_ulp) = read_number(num_text)?;
    Ok(Some(Reading {
        number,
        half_ulp,
        unit,
    }))
}

fn next_is_exponent(rest: &str) -> bool {
    let rest = rest.strip_prefix(['+', '-']).unwrap_or(rest);
    rest.starts_with(|c: char| c.is_ascii_digit())
}

/// A number without unit: decimal (point or comma), `1.2e-3`,
/// `1.2*10^-3`, or a fraction `a/b`.
fn read_number(s: &str) -> Result<(f64, f64), String> {
    if let Some((a, b)) = s.split_once('/') {
        let (x, _) = read_decimal(a)?;
        let (y, _) = read_decimal(b)?;
        if y == 0.0 {
            return Err(format!("\"{s}\" divides by zero"));
        }
        return Ok((x / y, 0.0));
    }
    let (mantissa, exponent) = if let Some((m, e)) = s.split_once("*10^") {
        (m, Some(e))
    } else if let Some(i) = s.find(['e', 'E']) {
        (&s[..i], Some(&s[i + 1..]))
    } else {
        (s, None)
    };
    let (m, half) = read_decimal(mantissa)?;
    match exponent {
        None => Ok((m, half)),
        Some(e) => {
            let e = e.strip_prefix('+').unwrap_or(e);
            let k: i32 = e
                .parse()
                .ok()
                .filter(|k: &i32| k.abs() <= 300)
                .ok_or_else(|| format!("\"{e}\" is not a whole-number exponent"))?;
            let p = 10f64.powi(k);
            Ok((m * p, half * p))
        }
    }
}

/// A plain decimal with a point or a comma; returns the value and half a
/// unit of its last digit.
fn read_decimal(s: &str) -> Result<(f64, f64), String> {
    let s = s.trim();
    let unsigned = s.strip_prefix(['+', '-']).unwrap_or(s);
    let seps = unsigned.matches(['.', ',']).count();
    let ok = !unsigned.is_empty()
        && seps <= 1
        && unsigned
            .chars()
            .all(|c| c.is_ascii_digit() || c == '.' || c == ',')
        && unsigned.chars().any(|c| c.is_ascii_digit());
    if !ok {
        return Err(format!("\"{s}\" is not a number"));
    }
    let normal = s.replace(',', ".");
    let x: f64 = normal
        .parse()
        .map_err(|_| format!("\"{s}\" is not a number"))?;
    let decimals = normal.split_once('.').map_or(0, |(_, f)| f.len());
    let half = 0.5 * 10f64.powi(-(decimals.min(300) as i32));
    Ok((x, half))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn n(s: &str) -> f64 {
        read(s).unwrap().unwrap().number
    }

    #[test]
    fn reads_the_usual_forms() {
        assert_eq!(n("0.0282"), 0.0282);
        assert_eq!(n("0,0282"), 0.0282);
        assert_eq!(n(" −12.5 "), -12.5);
        assert_eq!(n("2.5e-3"), 0.0025);
        assert_eq!(n("2,5E3"), 2500.0);
        assert!((n("2.5×10^-3") - 0.0025).abs() < 1e-15);
        assert_eq!(n("3/4"), 0.75);
        assert_eq!(n("-1/2"), -0.5);
        assert_eq!(read("").unwrap(), None);
        assert_eq!(read("   ").unwrap(), None);
    }

    #[test]
    fn reads_precision_and_units() {
        let r = read("26.7 cm").unwrap().unwrap();
        assert_eq!((r.number, r.unit), (26.7, Some("cm")));
        assert!((r.half_ulp - 0.05).abs() < 1e-12);
        assert_eq!(read("3/4").unwrap().unwrap().half_ulp, 0.0);
        let e = read("1.5e2").unwrap().unwrap();
        assert!((e.half_ulp - 5.0).abs() < 1e-9);
        assert_eq!(read("12°").unwrap().unwrap().unit, Some("°"));
        assert_eq!(read("8 px").unwrap().unwrap().unit, Some("px"));
    }

    #[test]
    fn malformed_texts_say_why() {
        for bad in [
            "abc",
            "1.2.3",
            "1,2,3",
            "--4",
            "1/0",
            "12 34",
            "5 parsecs",
            "e5",
        ] {
            assert!(read(bad).is_err(), "{bad} should not read");
        }
    }

    #[test]
    fn units_convert_within_a_dimension() {
        assert_eq!(
            check_unit(Some("mm"), Some("cm")),
            UnitCheck::Fits { factor: 0.1 }
        );
        assert_eq!(check_unit(Some("px"), Some("mm")), UnitCheck::Wrong);
        assert_eq!(
            check_unit(Some("m"), Some("km")),
            UnitCheck::Fits { factor: 0.001 }
        );
        assert_eq!(
            check_unit(Some("mm/km"), Some("ppm")),
            UnitCheck::Fits { factor: 1.0 }
        );
        assert_eq!(check_unit(Some("ppm"), Some("km")), UnitCheck::Wrong);
        let r = read("180,6 km").unwrap().unwrap();
        assert_eq!((r.number, r.unit), (180.6, Some("km")));
        assert_eq!(read("128 ppm").unwrap().unwrap().unit, Some("ppm"));
        assert_eq!(check_unit(None, Some("mm")), UnitCheck::Omitted);
        assert_eq!(check_unit(Some("mm"), None), UnitCheck::Wrong);
    }
}
