//! Photos the lab does not decode, recognised by their signatures and
//! refused with a way to a JPEG: HEIC/HEIF and AVIF (ISO base media files,
//! told by their `ftyp` brands), Canon CR3 (`ftyp` brand `crx `), and
//! camera RAW files — Fujifilm RAF (`FUJIFILMCCD-RAW`), Olympus ORF
//! (`IIRO`, `IIRS`, `MMOR`), Panasonic RW2 (`IIU\0`), Canon CR2 (a TIFF with
//! `CR` after its header), Canon CRW, Minolta MRW, Sigma X3F, and the
//! TIFF-based RAWs of the other makers (NEF, ARW, PEF, SRW, …) by what
//! their first IFD says (below).
//!
//! A TIFF-based RAW's first IFD, the image a TIFF decoder opens, is not the
//! photo: it is a small preview (NewSubfileType 1) with the sensor data in
//! a SubIFD, or the sensor's colour-filter mosaic itself (photometric CFA,
//! or a maker's own compression). Such a file is refused, never opened as
//! its thumbnail. A DNG (Adobe's RAW, a TIFF with `DNGVersion`) whose first
//! IFD is a full-resolution grey or RGB image may open through the TIFF
//! decoder like any TIFF ([`Tiff::Dng`]); when that decoding fails, the
//! error is the RAW message, not a TIFF one.

/// How to get a JPEG from a camera RAW file.
const RAW_WAY: &str = "Export it as a JPEG from the camera's app or a photo program (Lightroom, darktable, the camera maker's software, or the phone's Photos) and open the JPEG.";
/// How to get a JPEG from an iPhone's HEIC photo.
const HEIC_WAY: &str = "On the iPhone, Settings → Camera → Formats → Most Compatible makes the camera take JPEGs; for this photo, share or export it as JPEG (or open it on a computer and export it as JPEG) and open the JPEG.";

/// The words of the refusal of a camera RAW file described as `what`.
pub fn raw_message(what: &str) -> String {
    format!("is a camera RAW file ({what}): the sensor's undeveloped data, which the lab does not read. {RAW_WAY}")
}

/// What the signature says about a file the lab refuses, or `None` for a
/// file that goes on to the decoders. The text follows the file's name.
pub fn refused(name: &str, bytes: &[u8]) -> Option<String> {
    let at = |i: usize, sig: &[u8]| bytes.get(i..i + sig.len()) == Some(sig);
    if at(4, b"ftyp") {
        return Some(iso_media(bytes));
    }
    let raw = |what: &str| Some(raw_message(what));
    if at(0, b"FUJIFILMCCD-RAW") {
        return raw("Fujifilm RAF");
    }
    if at(0, b"IIRO") || at(0, b"IIRS") || at(0, b"MMOR") {
        return raw("Olympus ORF");
    }
    if at(0, b"IIU\0") {
        return raw("Panasonic RW2");
    }
    if at(0, b"II\x1a\0\0\0HEAPCCDR") {
        return raw("Canon CRW");
    }
    if at(0, b"\0MRM") {
        return raw("Minolta MRW");
    }
    if at(0, b"FOVb") {
        return raw("Sigma X3F");
    }
    match tiff(name, bytes) {
        Tiff::Raw(what) => raw(&what),
        Tiff::Dng | Tiff::Plain | Tiff::NotTiff => None,
    }
}

/// An ISO base media file (`ftyp` box at 4): HEIC/HEIF, AVIF, CR3, or a
/// video, by its major brand and then its compatible brands.
fn iso_media(bytes: &[u8]) -> String {
    let size = bytes
        .get(..4)
        .map_or(0, |b| u32::from_be_bytes([b[0], b[1], b[2], b[3]]) as usize);
    let end = size.clamp(16, 256).min(bytes.len());
    let major = bytes.get(8..12).unwrap_or(b"    ");
    // the major brand, then the compatible ones (from byte 16 on)
    let brands: Vec<&[u8]> = std::iter::once(major)
        .chain(bytes.get(16..end).unwrap_or(&[]).chunks_exact(4))
        .collect();
    // the first brand that names a kind decides; mif1/msf1 (any HEIF
    // image or sequence, AVIF files list them too) only when none does
    const HEVC: [&[u8]; 8] = [
        b"heic", b"heix", b"hevc", b"hevx", b"heim", b"heis", b"hevm", b"hevs",
    ];
    let kind = brands.iter().find_map(|b| match *b {
        b"avif" | b"avis" => Some("avif"),
        b"crx " => Some("crx"),
        b if HEVC.contains(&b) => Some("heif"),
        _ => None,
    });
    let kind = kind.or_else(|| {
        brands
            .iter()
            .any(|b| *b == b"mif1" || *b == b"msf1")
            .then_some("heif")
    });
    match kind {
        Some("crx") => return raw_message("Canon CR3"),
        Some("avif") => return "is an AVIF image, which the lab does not decode. Save or export it as JPEG or PNG (an image program, or a browser's screenshot of it) and open that.".to_string(),
        Some(_) => return format!("is a HEIC/HEIF photo (the iPhone's default format), which the lab does not decode. {HEIC_WAY}"),
        None => {}
    }
    let brand = String::from_utf8_lossy(major).trim().to_string();
    format!("is an ISO media file (brand \"{brand}\": a video or a sound, not a photo); the lab opens photos as JPEG, PNG, TIFF, WebP, BMP or GIF")
}

/// What a TIFF-like file is.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Tiff {
    /// Not a TIFF (its first bytes are not `II*\0` or `MM\0*`).
    NotTiff,
    /// A TIFF whose first image may be the photo.
    Plain,
    /// A DNG whose first IFD is a full-resolution grey or RGB image: it may
    /// open through the TIFF decoder.
    Dng,
    /// A camera RAW file, described (e.g. "Canon CR2", "Nikon NEF").
    Raw(String),
}

/// The tags of IFD0 that tell a RAW file.
#[derive(Default)]
struct Ifd0 {
    subfile: Option<u32>,
    compression: Option<u32>,
    photometric: Option<u32>,
    make: Option<String>,
    sub_ifds: bool,
    dng: bool,
}

/// The RAW kinds by file name extension (the TIFF-based ones).
const RAW_EXTENSIONS: [(&str, &str); 18] = [
    ("cr2", "Canon CR2"),
    ("nef", "Nikon NEF"),
    ("nrw", "Nikon NRW"),
    ("arw", "Sony ARW"),
    ("srf", "Sony SRF"),
    ("sr2", "Sony SR2"),
    ("pef", "Pentax PEF"),
    ("srw", "Samsung SRW"),
    ("3fr", "Hasselblad 3FR"),
    ("fff", "Hasselblad FFF"),
    ("erf", "Epson ERF"),
    ("kdc", "Kodak KDC"),
    ("dcr", "Kodak DCR"),
    ("mos", "Leaf MOS"),
    ("mef", "Mamiya MEF"),
    ("iiq", "Phase One IIQ"),
    ("rwl", "Leica RWL"),
    ("raw", "RAW"),
];

/// TIFF compression codes of the makers' RAW data: Sony (32767), Epson
/// (32769), Samsung (32770), Kodak (32867, 65000), Nikon (34713), Pentax
/// (65535).
const MAKER_COMPRESSIONS: [u32; 7] = [32767, 32769, 32770, 32867, 34713, 65000, 65535];

/// Whether `bytes` is a TIFF, and if so whether it is a camera RAW file.
pub fn tiff(name: &str, bytes: &[u8]) -> Tiff {
    let le = match bytes.get(..4) {
        Some(b"II*\0") => true,
        Some(b"MM\0*") => false,
        _ => return Tiff::NotTiff,
    };
    if bytes.get(8..10) == Some(b"CR") {
        return Tiff::Raw("Canon CR2".into());
    }
    let ifd = read_ifd0(bytes, le).unwrap_or_default();
    let ext = name
        .rsplit_once('.')
        .map(|(_, e)| e.to_ascii_lowercase())
        .unwrap_or_default();
    let by_ext = RAW_EXTENSIONS
        .iter()
        .find(|(e, _)| *e == ext)
        .map(|(_, w)| *w);
    let maker = ifd.make.as_deref().map(maker_name);
    let what = || {
        by_ext.map(str::to_string).unwrap_or_else(|| {
            maker.map_or("a TIFF-based RAW".into(), |m| format!("{m}, TIFF-based"))
        })
    };
    // the first image is a preview, a mosaic or in a maker's own compression
    let preview = ifd.subfile.is_some_and(|s| s & 1 == 1);
    let mosaic = matches!(ifd.photometric, Some(32803 | 34892));
    let maker_compression = ifd
        .compression
        .is_some_and(|c| MAKER_COMPRESSIONS.contains(&c));
    if ifd.dng || ext == "dng" {
        return if preview || mosaic || maker_compression || !matches!(ifd.photometric, Some(0..=2))
        {
            Tiff::Raw("DNG".into())
        } else {
            Tiff::Dng
        };
    }
    if by_ext.is_some()
        || mosaic
        || maker_compression
        || (ifd.make.is_some() && (preview || ifd.sub_ifds))
    {
        return Tiff::Raw(what());
    }
    Tiff::Plain
}

/// "NIKON CORPORATION" → "Nikon", "SONY" → "Sony", "Canon" → "Canon".
fn maker_name(make: &str) -> String {
    let word = make.split_whitespace().next().unwrap_or("camera");
    let mut chars = word.chars();
    chars.next().map_or_else(String::new, |f| {
        f.to_uppercase()
            .chain(chars.flat_map(char::to_lowercase))
            .collect()
    })
}

/// IFD0's tags that tell a RAW file; `None` when the IFD is not where the
/// header says (the TIFF decoder then says what is wrong).
fn read_ifd0(b: &[u8], le: bool) -> Option<Ifd0> {
    let u16_at = |i: usize| -> Option<u32> {
        let s = b.get(i..i + 2)?;
        Some(u32::from(if le {
            u16::from_le_bytes([s[0], s[1]])
        } else {
            u16::from_be_bytes([s[0], s[1]])
        }))
    };
    let u32_at = |i: usize| -> Option<u32> {
        let s: [u8; 4] = b.get(i..i + 4)?.try_into().ok()?;
        Some(if le {
            u32::from_le_bytes(s)
        } else {
            u32::from_be_bytes(s)
        })
    };
    let off = u32_at(4)? as usize;
    let n = u16_at(off)? as usize;
    let mut ifd = Ifd0::default();
    for k in 0..n.min(512) {
        let e = off + 2 + 12 * k;
        let (tag, typ, count) = (u16_at(e)?, u16_at(e + 2)?, u32_at(e + 4)?);
        // a SHORT or LONG value held in the entry
        let value = || match typ {
            3 => u16_at(e + 8),
            4 => u32_at(e + 8),
            _ => None,
        };
        match tag {
            254 => ifd.subfile = value(),
            259 => ifd.compression = value(),
            262 => ifd.photometric = value(),
            271 if typ == 2 => {
                let len = count as usize;
                let at = if len <= 4 {
                    e + 8
                } else {
                    u32_at(e + 8)? as usize
                };
                let text = b.get(at..at + len.min(64))?;
                let text = String::from_utf8_lossy(text);
                let text = text.trim_end_matches('\0').trim();
                if !text.is_empty() {
                    ifd.make = Some(text.to_string());
                }
            }
            330 => ifd.sub_ifds = true,
            50706 => ifd.dng = true,
            _ => {}
        }
    }
    Some(ifd)
}
