//! Angles as people write them: decimal degrees (`55.5`, `-6.25`) or
//! degrees, minutes and seconds (`55°30'12.5"N`, `55 30 12.5`, `55d30'`,
//! `55:30:12.5 S`, `W 6 15`). A hemisphere letter (N, S, E, W, either case)
//! may stand first or last instead of a sign; S and W make the angle
//! negative. Each number is read by the one number reader
//! ([`crate::read`]): a decimal point or comma (`55,5`).

use crate::read::{read_value, short};

/// Reads an angle in degrees; `pos`/`neg` are the hemisphere letters the
/// field allows (`'N'`/`'S'` for a latitude, `'E'`/`'W'` for a longitude).
/// The error says what is wrong, without the field name.
pub fn parse(text: &str, pos: char, neg: char) -> Result<f64, String> {
    let t = text.trim();
    if t.is_empty() {
        return Err(
            "is empty; enter degrees (55.5) or degrees, minutes, seconds (55°30'00\"N)".into(),
        );
    }
    let mut body = t.to_string();
    let mut sign = 1.0;
    let mut letter = None;
    let first = body.chars().next().map(|c| c.to_ascii_uppercase());
    let last = body.chars().last().map(|c| c.to_ascii_uppercase());
    for (c, at_end) in [(first, false), (last, true)] {
        let Some(c) = c else { continue };
        if !matches!(c, 'N' | 'S' | 'E' | 'W') {
            continue;
        }
        if c != pos && c != neg {
            return Err(format!(
                "\"{}\": {c} is not a hemisphere of this angle (use {pos} or {neg})",
                short(t)
            ));
        }
        if letter.is_some() {
            return Err(format!("\"{}\": two hemisphere letters", short(t)));
        }
        letter = Some(c);
        if at_end {
            body.pop();
        } else {
            body.remove(0);
        }
        if c == neg {
            sign = -1.0;
        }
    }
    let mut b = body.trim();
    if let Some(rest) = b.strip_prefix(['-', '−']) {
        if letter.is_some() {
            return Err(format!(
                "\"{}\": give either a minus sign or a hemisphere letter, not both",
                short(t)
            ));
        }
        sign = -1.0;
        b = rest.trim_start();
    } else if let Some(rest) = b.strip_prefix('+') {
        b = rest.trim_start();
    }
    let parts: Vec<&str> = b
        .split(|c: char| {
            c.is_whitespace() || matches!(c, '°' | '\'' | '"' | '′' | '″' | ':' | 'd' | 'º')
        })
        .filter(|s| !s.is_empty())
        .collect();
    if parts.is_empty() || parts.len() > 3 {
        return Err(format!(
            "\"{}\" is not an angle: give degrees (55.5) or degrees, minutes, seconds (55°30'12.5\"N)",
            short(t)
        ));
    }
    let mut numbers = [0.0; 3];
    for (i, p) in parts.iter().enumerate() {
        // each part on the one number reader's rules (a decimal point or comma)
        match read_value(p, None) {
            Ok(x) if x >= 0.0 && !p.starts_with('+') => numbers[i] = x,
            _ => {
                return Err(format!(
                    "\"{}\" is not an angle: \"{}\" is not a number of {}",
                    short(t),
                    short(p),
                    ["degrees", "minutes", "seconds"][i]
                ))
            }
        }
    }
    let names = ["degrees", "minutes", "seconds"];
    for i in 0..parts.len() - 1 {
        if numbers[i].fract() != 0.0 {
            return Err(format!(
                "\"{}\": the {} must be a whole number when {} follow",
                short(t),
                names[i],
                names[i + 1]
            ));
        }
    }
    for i in 1..parts.len() {
        if numbers[i] >= 60.0 {
            return Err(format!(
                "\"{}\": {} must be less than 60 (got {})",
                short(t),
                names[i],
                numbers[i]
            ));
        }
    }
    Ok(sign * (numbers[0] + numbers[1] / 60.0 + numbers[2] / 3600.0))
}

/// Degrees, minutes and seconds with `decimals` decimals of the second and
/// the hemisphere letter: `55°30′12.500″ N`.
pub fn format(deg: f64, pos: char, neg: char, decimals: usize) -> String {
    let letter = if deg < 0.0 { neg } else { pos };
    let scale = 10f64.powi(decimals as i32);
    let total = (deg.abs() * 3600.0 * scale).round();
    let whole_s = (total / scale).floor();
    let frac = total - whole_s * scale;
    let d = (whole_s / 3600.0).floor();
    let m = ((whole_s - d * 3600.0) / 60.0).floor();
    let s = whole_s - d * 3600.0 - m * 60.0;
    if decimals == 0 {
        format!("{d}°{m:02}′{s:02}″ {letter}")
    } else {
        format!(
            "{d}°{m:02}′{s:02}.{:0width$}″ {letter}",
            frac as u64,
            width = decimals
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn reads_degrees_and_dms() {
        let lat = |t| parse(t, 'N', 'S');
        assert_eq!(lat("55.5"), Ok(55.5));
        assert_eq!(lat("-6.25"), Ok(-6.25));
        assert_eq!(lat("55°30'00\"N"), Ok(55.5));
        assert_eq!(lat("55 30 36"), Ok(55.51));
        assert_eq!(lat("S 33 52.5"), Ok(-(33.0 + 52.5 / 60.0)));
        assert_eq!(lat("33:52:30 s"), Ok(-(33.0 + 52.5 / 60.0)));
        assert_eq!(lat("55d30′"), Ok(55.5));
        assert_eq!(lat("−12.5"), Ok(-12.5));
        assert!(lat("55 60").unwrap_err().contains("less than 60"));
        assert!(lat("55.5 30").unwrap_err().contains("whole number"));
        assert!(lat("55E").unwrap_err().contains("not a hemisphere"));
        assert!(lat("-55S").unwrap_err().contains("not both"));
        assert!(lat("NaN").is_err());
        assert!(lat("abc").unwrap_err().contains("not a number"));
        assert!(lat("1 2 3 4").is_err());
        assert!(lat("").is_err());
        assert_eq!(parse("6 15 W", 'E', 'W'), Ok(-6.25));
    }

    #[test]
    fn writes_dms() {
        assert_eq!(format(55.51, 'N', 'S', 3), "55°30′36.000″ N");
        assert_eq!(format(-6.25, 'E', 'W', 0), "6°15′00″ W");
        assert_eq!(format(12.999_999_99, 'E', 'W', 2), "13°00′00.00″ E");
    }
}
