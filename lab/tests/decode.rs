//! Decoding: known pixel values for every format the lab reads, photos
//! upright by their EXIF orientation and reduced to the working size, HEIC,
//! AVIF and RAW files refused with a way to a JPEG, and a clear error naming
//! the file and the reason for every file of the bad corpus.

use photogrammetry_lab::decode::{decode, grey, luma, probe, Decoded};
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
        ("text.png", "not a PNG, JPEG or TIFF image, nor a WebP, BMP or GIF"),
        ("truncated.png", "PNG"),
        ("bad_crc.png", "PNG file is damaged"),
        ("zero_width.png", "PNG"),
        (
            "huge_header.png",
            "too large to open here (at most 16384 pixels across or down and 48 megapixels in all)",
        ),
        (
            "bomb.png",
            "says 7200×7200 pixels (51.8 megapixels): too large to open here (at most 16384 pixels across or down and 48 megapixels in all)",
        ),
        ("missing_tag.tif", "TIFF"),
        ("truncated.jpg", "JPEG"),
        (
            "unsupported.qoi",
            "is a QOI image, a format the lab does not read: it opens PNG, JPEG, TIFF, WebP, BMP and GIF",
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

/// Writes the JPEGs and the WebP of the corpus (run by hand: `cargo test -p
/// photogrammetry-lab --test decode -- --ignored`).
#[test]
#[ignore]
fn write_encoded() {
    use image::codecs::jpeg::JpegEncoder;
    use image::codecs::webp::WebPEncoder;
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
    // 24 × 16 in six flat 8×8 blocks (block6), with each EXIF orientation
    let blocks: Vec<u8> = (0..16)
        .flat_map(|r| (0..24).map(move |c| block6(c, r) as u8))
        .collect();
    let mut plain = Vec::new();
    JpegEncoder::new_with_quality(&mut plain, 100)
        .encode(&blocks, 24, 16, ExtendedColorType::L8)
        .unwrap();
    for o in 1..=8 {
        std::fs::write(dir.join(format!("orient_{o}.jpg")), with_exif(&plain, o)).unwrap();
    }
    // a lossless WebP of rgb8
    let px: Vec<u8> = (0..3)
        .flat_map(|r| (0..4).flat_map(move |c| [50 * c, 60 * r, 200 - 30 * c]))
        .map(|v| v as u8)
        .collect();
    let mut out = Vec::new();
    WebPEncoder::new_lossless(&mut out)
        .encode(&px, 4, 3, ExtendedColorType::Rgb8)
        .unwrap();
    std::fs::write(dir.join("rgb8.webp"), &out).unwrap();
}

// ---------------------------------------------------------------- photos as they are taken

/// The orientation JPEGs' pixels as stored: 24 × 16 in six flat 8×8 blocks,
/// each its own grey value (flat blocks at quality 100 decode exactly).
fn block6(c: usize, r: usize) -> f64 {
    (20 + 40 * (c / 8 + 3 * (r / 8))) as f64
}

/// `jpeg` with an APP1 EXIF segment holding only Orientation (tag 0x0112)
/// = `o`, right after its SOI marker (big-endian TIFF, one IFD entry).
fn with_exif(jpeg: &[u8], o: u16) -> Vec<u8> {
    let mut app1 = vec![0xFF, 0xE1, 0, 34];
    app1.extend_from_slice(b"Exif\0\0MM\0\x2a\0\0\0\x08\0\x01");
    app1.extend_from_slice(&[0x01, 0x12, 0, 3, 0, 0, 0, 1]);
    app1.extend_from_slice(&o.to_be_bytes());
    app1.extend_from_slice(&[0, 0, 0, 0, 0, 0]);
    assert_eq!(app1.len(), 36);
    [&jpeg[..2], &app1[..], &jpeg[2..]].concat()
}

#[test]
fn each_exif_orientation_is_applied_upright() {
    // where the stored pixel (x, y) of the 24 × 16 photo lands, as EXIF
    // defines each orientation (the browser shows the photo so)
    let lands = |o: u8, x: usize, y: usize| -> (usize, usize) {
        let (w, h) = (24, 16);
        match o {
            1 => (x, y),
            2 => (w - 1 - x, y),         // mirrored left to right
            3 => (w - 1 - x, h - 1 - y), // turned 180°
            4 => (x, h - 1 - y),         // mirrored top to bottom
            5 => (y, x),                 // transposed
            6 => (h - 1 - y, x), // turned 90° clockwise: the top row becomes the right column
            7 => (h - 1 - y, w - 1 - x),
            8 => (y, w - 1 - x), // turned 90° counter-clockwise
            _ => unreachable!(),
        }
    };
    let words = [
        None,
        Some("mirrored left to right"),
        Some("turned 180°"),
        Some("mirrored top to bottom"),
        Some("turned 90° clockwise and mirrored left to right"),
        Some("turned 90° clockwise"),
        Some("turned 90° counter-clockwise and mirrored left to right"),
        Some("turned 90° counter-clockwise"),
    ];
    for o in 1..=8u8 {
        let name = format!("orient_{o}.jpg");
        let d = open(&name);
        let (w, h) = if o >= 5 { (16, 24) } else { (24, 16) };
        assert_eq!((d.grid.width(), d.grid.height()), (w, h), "{name}");
        assert_eq!((d.photo.orientation, d.photo.factor), (o, 1), "{name}");
        assert_eq!((d.photo.width, d.photo.height), (w, h), "{name}");
        for y in 0..16 {
            for x in 0..24 {
                let (u, v) = lands(o, x, y);
                assert_eq!(
                    d.grid.get(u, v),
                    Some(block6(x, y)),
                    "{name}: ({x}, {y}) → ({u}, {v})"
                );
            }
        }
        // the stored top-left block (20) is where the orientation puts it
        let want = words[usize::from(o) - 1].map(|w| format!("{w} by its EXIF orientation ({o})"));
        assert_eq!(d.photo.turned(), want, "{name}");
        // the header alone says the same
        let (format, p) = probe(&name, &read(&name)).unwrap();
        assert_eq!((format, p), ("JPEG", d.photo));
    }
    // 6: the stored top-left block, 20, is now at the top right
    let d = open("orient_6.jpg");
    assert_eq!(
        (d.grid.get(15, 0), d.grid.get(0, 0)),
        (Some(20.0), Some(140.0))
    );
}

#[test]
fn upright_agrees_with_the_image_crates_apply_orientation() {
    use image::metadata::Orientation;
    use image::{DynamicImage, RgbImage};
    // a 7 × 5 colour photo of distinct pixels
    let img = RgbImage::from_fn(7, 5, |x, y| {
        image::Rgb([(x * 31 + y * 7) as u8, (y * 50) as u8, (x * 3 + 100) as u8])
    });
    for o in 1..=8u8 {
        let mut turned = DynamicImage::ImageRgb8(img.clone());
        turned.apply_orientation(Orientation::from_exif(o).unwrap());
        let t = turned.to_rgb8();
        let (uw, uh) = grey::upright_size(o, 7, 5);
        assert_eq!((t.width() as usize, t.height() as usize), (uw, uh), "{o}");
        let (g, _) = grey::grey(&DynamicImage::ImageRgb8(img.clone()), o, 1, (uw, uh)).unwrap();
        for v in 0..uh {
            for u in 0..uw {
                let p = t.get_pixel(u as u32, v as u32).0;
                let want = luma(f64::from(p[0]), f64::from(p[1]), f64::from(p[2]));
                assert_eq!(g[v * uw + u], want, "orientation {o} at ({u}, {v})");
            }
        }
    }
}

#[test]
fn reduction_by_k_is_the_exact_area_average_of_k_by_k_blocks() {
    use image::{DynamicImage, GrayImage, ImageBuffer, Luma};
    // 8-bit grey 7 × 5 by 2: 3 × 2 blocks, the last column and row left out
    let img = GrayImage::from_fn(7, 5, |x, y| Luma([(x * 13 + y * 29) as u8]));
    let (g, kind) = grey::grey(&DynamicImage::ImageLuma8(img.clone()), 1, 2, (3, 2)).unwrap();
    assert_eq!(kind, ("grey", 8, 255.0));
    let at = |x: u32, y: u32| f64::from(img.get_pixel(x, y).0[0]);
    for (i, &got) in g.iter().enumerate() {
        let (u, v) = (i as u32 % 3, i as u32 / 3);
        let sum = at(2 * u, 2 * v)
            + at(2 * u + 1, 2 * v)
            + at(2 * u, 2 * v + 1)
            + at(2 * u + 1, 2 * v + 1);
        assert_eq!(got, sum / 4.0, "block ({u}, {v})");
    }
    // (0, 0): (0 + 13 + 29 + 42) / 4 = 21
    assert_eq!(g[0], 21.0);
    // by 3, turned 90° clockwise (6): the blocks of the upright photo
    let (g, _) = grey::grey(&DynamicImage::ImageLuma8(img.clone()), 6, 3, (1, 2)).unwrap();
    let up = |u: usize, v: usize| at(v as u32, (4 - u) as u32); // upright (u, v) = stored (v, h − 1 − u)
    for (bv, &got) in g.iter().enumerate() {
        let sum: f64 = (0..3)
            .flat_map(|dv| (0..3).map(move |du| (du, dv)))
            .map(|(du, dv)| up(du, 3 * bv + dv))
            .sum();
        assert_eq!(got, sum / 9.0, "block (0, {bv})");
    }
    // colour 16-bit by 2: the average of the four pixels' lumas
    let img: ImageBuffer<image::Rgb<u16>, Vec<u16>> = ImageBuffer::from_fn(4, 2, |x, y| {
        image::Rgb([
            (x * 9000 + 1) as u16,
            (y * 30000 + 2) as u16,
            60000 - (x * 7000) as u16,
        ])
    });
    let (g, kind) = grey::grey(&DynamicImage::ImageRgb16(img.clone()), 1, 2, (2, 1)).unwrap();
    assert_eq!(kind, ("colour", 16, 65535.0));
    for (u, &got) in g.iter().enumerate() {
        let l = |x: u32, y: u32| {
            let p = img.get_pixel(x, y).0;
            luma(f64::from(p[0]), f64::from(p[1]), f64::from(p[2]))
        };
        let x = 2 * u as u32;
        let want = (l(x, 0) + l(x + 1, 0) + l(x, 1) + l(x + 1, 1)) / 4.0;
        assert!((got - want).abs() < 1e-9, "{got} vs {want}");
    }
}

#[test]
fn webp_bmp_and_gif_decode_with_their_known_pixels() {
    let d = open("rgb8.webp");
    assert_eq!((d.format, d.colour, d.bits), ("WebP", "colour", 8));
    check(&d, rgb8);
    let d = open("rgb8.bmp");
    assert_eq!((d.format, d.colour, d.bits), ("BMP", "colour", 8));
    check(&d, rgb8);
    // the first of the GIF's two frames (the second is all 255)
    let d = open("grey8.gif");
    assert_eq!((d.format, d.bits), ("GIF", 8));
    check(&d, grey8);
}

#[test]
fn heic_avif_and_raw_files_are_refused_with_a_way_to_a_jpeg() {
    let heic = "is a HEIC/HEIF photo (the iPhone's default format), which the lab does not decode. On the iPhone, Settings → Camera → Formats → Most Compatible makes the camera take JPEGs; for this photo, share or export it as JPEG";
    let raw = |what: &str| {
        format!("is a camera RAW file ({what}): the sensor's undeveloped data, which the lab does not read. Export it as a JPEG from the camera's app")
    };
    let cases = [
        ("iphone.heic", heic.to_string()),
        (
            "photo.avif",
            "is an AVIF image, which the lab does not decode. Save or export it as JPEG or PNG"
                .to_string(),
        ),
        ("canon.cr3", raw("Canon CR3")),
        ("fuji.raf", raw("Fujifilm RAF")),
        ("olympus.orf", raw("Olympus ORF")),
        ("panasonic.rw2", raw("Panasonic RW2")),
        // TIFFs whose first image would decode (4 × 3): not opened as the photo
        ("canon.cr2", raw("Canon CR2")),
        ("nikon.nef", raw("Nikon NEF")),
        ("preview.dng", raw("DNG")),
    ];
    for (name, says) in &cases {
        let m = err(name);
        assert!(m.starts_with(&format!("{name}: {says}")), "{m}");
        // the header alone refuses it the same way
        assert_eq!(probe(name, &read(name)).unwrap_err().to_string(), m);
    }
    // by its maker and its thumbnail IFD, whatever it is called
    let m = decode("DSC_0001.tif", &read("nikon.nef"))
        .unwrap_err()
        .to_string();
    assert!(m.contains(&raw("Nikon, TIFF-based")), "{m}");
    // by its name: a TIFF called .ARW
    let m = decode("DSC01234.ARW", &read("rgb8_tiles.tif"))
        .unwrap_err()
        .to_string();
    assert!(m.contains(&raw("Sony ARW")), "{m}");
    // HEIC brands: major mif1 with heic among the compatible ones; AVIF's mif1 is AVIF
    let ftyp = |major: &[u8], compat: &[&[u8]]| {
        let body = [major, &[0u8; 4][..], &compat.concat()].concat();
        [&((8 + body.len()) as u32).to_be_bytes()[..], b"ftyp", &body].concat()
    };
    for (bytes, says) in [
        (ftyp(b"mif1", &[b"mif1", b"heic"]), "HEIC/HEIF"),
        (ftyp(b"heix", &[b"mif1"]), "HEIC/HEIF"),
        (ftyp(b"msf1", &[b"msf1", b"hevc"]), "HEIC/HEIF"),
        (ftyp(b"mif1", &[b"avif", b"mif1", b"miaf"]), "AVIF"),
        (ftyp(b"avis", &[b"avis", b"msf1"]), "AVIF"),
        (
            ftyp(b"isom", &[b"isom", b"mp41"]),
            "a video or a sound, not a photo",
        ),
    ] {
        let m = decode("x", &bytes).unwrap_err().to_string();
        assert!(m.contains(says), "{m}");
    }
    // a DNG whose first image is the full photo opens as the TIFF it is
    let d = open("full.dng");
    assert_eq!(d.format, "TIFF");
    check(&d, rgb8);
}

/// A grey PNG of `w × h` whose pixels are all `v` (stored uncompressed
/// deflate blocks would be large: zlib of a repeated row).
fn flat_png(w: u32, h: u32, v: u8) -> Vec<u8> {
    let mut out = Vec::new();
    image::codecs::png::PngEncoder::new(&mut out)
        .write_image(
            &vec![v; (w * h) as usize],
            w,
            h,
            image::ExtendedColorType::L8,
        )
        .unwrap();
    out
}

use image::ImageEncoder;

#[test]
fn a_48_megapixel_photo_is_reduced_to_the_working_size_and_more_is_refused() {
    // an 8064 × 6048 camera photo (48.8 million pixels): reduced 2×
    let d = decode("camera.png", &flat_png(8064, 6048, 77)).unwrap();
    assert_eq!((d.grid.width(), d.grid.height()), (4032, 3024));
    assert_eq!(d.photo.factor, 2);
    assert_eq!((d.photo.width, d.photo.height), (8064, 6048));
    assert!(d.grid.data().iter().all(|&v| v == 77.0));
    assert_eq!(
        d.photo.reduced().unwrap(),
        "reduced 2× (area average of 2 × 2 pixels) from 8064 × 6048 to 4032 × 3024 pixels to fit the lab's working size of 16 megapixels; 1 lab pixel = 2 × 2 photo pixels"
    );
    // the working size itself is not reduced; one pixel more is
    assert_eq!(grey_size(4096, 4096), (4096, 4096, 1));
    assert_eq!(grey_size(4097, 4096), (2048, 2048, 2));
    assert_eq!(grey_size(16384, 1024), (16384, 1024, 1));
    assert_eq!(grey_size(4000, 3000), (4000, 3000, 1));
    // over 48 megapixels (7200 × 7200), or over 16384 across: refused with the limits
    for (w, h) in [(7200, 7200), (16385, 100)] {
        let m = decode("big.png", &flat_png(w, h, 0))
            .unwrap_err()
            .to_string();
        assert!(
            m.contains("at most 16384 pixels across or down and 48 megapixels in all"),
            "{m}"
        );
    }
}

/// The working size and factor of a `w × h` photo, from its header.
fn grey_size(w: u32, h: u32) -> (usize, usize, usize) {
    let (_, p) = probe("p.png", &flat_png(w, h, 1)).unwrap();
    (p.work_width, p.work_height, p.factor)
}
