//! Decoding: known pixel values for every format the lab reads, and a clear
//! error naming the file and the reason for every file of the bad corpus.

use photogrammetry_lab::decode::{decode, luma, Decoded};
use std::path::Path;

fn read(name: &str) -> Vec<u8> {
    let p = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/corpus")
        .join(name);
    std::fs::read(&p).unwrap_or_else(|e| panic!("{}: {e}", p.display()))
}

fn open(name: &str) -> Decoded {
    decode(name, &read(name)).unwrap_or_else(|e| panic!("{name}: {e}"))
}

fn err(name: &str) -> String {
    match decode(name, &read(name)) {
        Ok(d) => panic!("{name} decoded to {}×{}", d.grid.width(), d.grid.height()),
        Err(e) => e.to_string(),
    }
}

// The corpus's known pixels (make_corpus.py).
fn grey8(c: usize, r: usize) -> f64 {
    (10 * c + 40 * r) as f64
}
fn grey16(c: usize, r: usize) -> f64 {
    (1000 * c + 20000 * r + 7) as f64
}
fn rgb8(c: usize, r: usize) -> f64 {
    luma((50 * c) as f64, (60 * r) as f64, (200 - 30 * c) as f64)
}
fn rgb16(c: usize, r: usize) -> f64 {
    luma(
        (10000 * c + 1) as f64,
        (15000 * r + 2) as f64,
        (60000 - 9000 * c) as f64,
    )
}

fn check(d: &Decoded, f: fn(usize, usize) -> f64) {
    assert_eq!((d.grid.width(), d.grid.height()), (4, 3));
    for r in 0..3 {
        for c in 0..4 {
            let got = d.grid.get(c, r).unwrap();
            assert!(
                (got - f(c, r)).abs() < 1e-9,
                "({c}, {r}): {got} ≠ {}",
                f(c, r)
            );
        }
    }
}

#[test]
fn bt601_luma_weights() {
    assert_eq!(luma(255.0, 255.0, 255.0), 255.0);
    assert!((luma(100.0, 0.0, 0.0) - 29.9).abs() < 1e-12);
    assert!((luma(0.0, 100.0, 0.0) - 58.7).abs() < 1e-12);
    assert!((luma(0.0, 0.0, 100.0) - 11.4).abs() < 1e-12);
    // the f64 nearest the exact luma: at most three decimals when printed
    for (r, g, b) in [(187, 190, 180), (1, 2, 3), (255, 0, 17), (65535, 1, 40000)] {
        let v = luma(f64::from(r), f64::from(g), f64::from(b));
        let thousandths = 299 * r + 587 * g + 114 * b;
        assert_eq!((v * 1000.0).round(), f64::from(thousandths));
        let text = v.to_string();
        assert!(text.split('.').nth(1).map_or(0, str::len) <= 3, "{text}");
    }
}

#[test]
fn png_grey_8_and_16_bit_and_rgb() {
    let d = open("grey8.png");
    assert_eq!(
        (d.format, d.colour, d.bits, d.max_value),
        ("PNG", "grey", 8, 255.0)
    );
    check(&d, grey8);
    let d = open("grey16.png");
    assert_eq!((d.bits, d.max_value), (16, 65535.0));
    // 16-bit precision kept: 43007 is not a multiple of 257
    assert_eq!(d.grid.get(3, 2), Some(43007.0));
    check(&d, grey16);
    let d = open("rgb8.png");
    assert_eq!(d.colour, "colour");
    check(&d, rgb8);
}

#[test]
fn tiff_8_and_16_bit_grey_and_rgb_strips_and_tiles() {
    let d = open("grey8_strips.tif");
    assert_eq!((d.format, d.bits), ("TIFF", 8));
    check(&d, grey8);
    let d = open("grey16_strips.tif");
    assert_eq!(d.bits, 16);
    check(&d, grey16);
    let d = open("rgb8_tiles.tif");
    assert_eq!(d.colour, "colour");
    check(&d, rgb8);
    let d = open("rgb16_strips.tif");
    assert_eq!((d.colour, d.bits), ("colour", 16));
    check(&d, rgb16);
}

// The 40 × 24 TIFFs of several tiles and with Deflate (make_corpus.py).
fn tile8(c: usize, r: usize) -> f64 {
    ((7 * c + 11 * r) % 256) as f64
}
fn tile16(c: usize, r: usize) -> f64 {
    (1000 * c + 1000 * r + 7) as f64
}

fn check_40x24(d: &Decoded, f: fn(usize, usize) -> f64) {
    assert_eq!((d.grid.width(), d.grid.height()), (40, 24));
    for r in 0..24 {
        for c in 0..40 {
            assert_eq!(d.grid.get(c, r), Some(f(c, r)), "({c}, {r})");
        }
    }
}

#[test]
fn tiff_in_several_tiles_8_and_16_bit_and_deflate_compressed() {
    // 3 × 2 tiles of 16 × 16, the right column and bottom row padded:
    // every pixel from the right tile, none from the padding
    let d = open("grey8_tiles.tif");
    assert_eq!((d.format, d.colour, d.bits), ("TIFF", "grey", 8));
    check_40x24(&d, tile8);
    let d = open("grey16_tiles.tif");
    assert_eq!((d.format, d.bits, d.max_value), ("TIFF", 16, 65535.0));
    // 16-bit precision kept: 62007 = (39 + 23)·1000 + 7 at the last pixel
    assert_eq!(d.grid.get(39, 23), Some(62007.0));
    check_40x24(&d, tile16);
    let d = open("grey8_deflate.tif");
    assert_eq!((d.format, d.bits), ("TIFF", 8));
    check_40x24(&d, tile8);
}

#[test]
fn jpeg_flat_blocks_decode_exactly() {
    // 16×8: a left block of 50 and a right block of 200 (flat 8×8 blocks
    // keep only their DC term, which quality 100 stores exactly).
    let d = open("blocks.jpg");
    assert_eq!((d.format, d.colour, d.bits), ("JPEG", "grey", 8));
    assert_eq!((d.grid.width(), d.grid.height()), (16, 8));
    for r in 0..8 {
        for c in 0..16 {
            let want = if c < 8 { 50.0 } else { 200.0 };
            assert_eq!(d.grid.get(c, r), Some(want), "({c}, {r})");
        }
    }
    // colour: flat (200, 100, 50) through YCbCr and back, ±1 per channel
    let d = open("colour.jpg");
    assert_eq!(d.colour, "colour");
    let want = luma(200.0, 100.0, 50.0);
    for &v in d.grid.data() {
        assert!((v - want).abs() <= 1.0, "{v} vs {want}");
    }
}

#[test]
fn bad_files_name_the_file_and_the_reason() {
    let cases: &[(&str, &str)] = &[
        ("empty.png", "empty"),
        ("text.png", "not a PNG, JPEG or TIFF"),
        ("truncated.png", "PNG"),
        ("bad_crc.png", "PNG file is damaged"),
        ("zero_width.png", "PNG"),
        ("huge_header.png", "too large"),
        ("bomb.png", "at most 16 megapixels"),
        ("missing_tag.tif", "TIFF"),
        ("truncated.jpg", "JPEG"),
        (
            "unsupported.gif",
            "is a GIF image, a format the lab does not read: it opens PNG, JPEG and TIFF",
        ),
    ];
    for (name, says) in cases {
        let m = err(name);
        assert!(m.starts_with(&format!("{name}: ")), "{m}");
        assert!(m.contains(says), "{name}: {m}");
    }
}

#[test]
fn the_bundled_samples_decode() {
    let www = Path::new(env!("CARGO_MANIFEST_DIR")).join("../www/lab/samples");
    for (name, w, h, colour) in [
        ("aero1.jpg", 0, 0, "colour"),
        ("left01.jpg", 640, 480, "grey"),
        ("camera.png", 512, 512, "grey"),
        ("brick.png", 512, 512, "grey"),
    ] {
        let bytes = std::fs::read(www.join(name)).unwrap();
        let d = decode(name, &bytes).unwrap();
        if w > 0 {
            assert_eq!((d.grid.width(), d.grid.height()), (w, h), "{name}");
        }
        assert_eq!(d.colour, colour, "{name}");
        assert!(d.grid.data().iter().all(|v| (0.0..=255.0).contains(v)));
    }
}

/// Writes the JPEGs of the corpus (run by hand: `cargo test -p
/// photogrammetry-lab --test decode -- --ignored`).
#[test]
#[ignore]
fn write_jpegs() {
    use image::codecs::jpeg::JpegEncoder;
    use image::ExtendedColorType;
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/corpus");
    let grey: Vec<u8> = (0..8)
        .flat_map(|_| (0..16).map(|c| if c < 8 { 50u8 } else { 200 }))
        .collect();
    let mut out = Vec::new();
    JpegEncoder::new_with_quality(&mut out, 100)
        .encode(&grey, 16, 8, ExtendedColorType::L8)
        .unwrap();
    std::fs::write(dir.join("blocks.jpg"), &out).unwrap();
    let colour: Vec<u8> = (0..64).flat_map(|_| [200u8, 100, 50]).collect();
    let mut out = Vec::new();
    JpegEncoder::new_with_quality(&mut out, 100)
        .encode(&colour, 8, 8, ExtendedColorType::Rgb8)
        .unwrap();
    std::fs::write(dir.join("colour.jpg"), &out).unwrap();
    // a truncated photo: the first 40 % of aero3.jpg
    let aero = std::fs::read(dir.join("../../../www/lab/samples/aero3.jpg")).unwrap();
    std::fs::write(dir.join("truncated.jpg"), &aero[..aero.len() * 2 / 5]).unwrap();
}
