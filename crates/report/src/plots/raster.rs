//! Maps of many cells as one image: an RGBA PNG (uncompressed deflate blocks, so no
//! compression library is needed), embedded in the SVG as a base64 `data:` URI. One
//! `<rect>` per cell costs about 100 bytes; a pixel costs 4 bytes before base64, so a
//! 160 x 160 map takes about 140 kB instead of 2.6 MB.

/// The colour that marks where the image goes: plotters draws a rectangle of it over the
/// plot area, and [`embed`] replaces that element by the image. No map draws this colour
/// (the diverging and sequential scales and the stick/slip colours stay far from it).
pub(crate) const MARKER: (u8, u8, u8) = (1, 2, 3);

/// CRC-32 (ISO 3309, as PNG chunks use it) of `bytes`.
fn crc32(bytes: &[u8]) -> u32 {
    let mut c = 0xffff_ffffu32;
    for &b in bytes {
        c ^= u32::from(b);
        for _ in 0..8 {
            c = if c & 1 == 1 { 0xedb8_8320 ^ (c >> 1) } else { c >> 1 };
        }
    }
    !c
}

/// Adler-32 (RFC 1950) of `bytes`.
fn adler32(bytes: &[u8]) -> u32 {
    let (mut a, mut b) = (1u32, 0u32);
    for chunk in bytes.chunks(5552) {
        for &x in chunk {
            a += u32::from(x);
            b += a;
        }
        a %= 65521;
        b %= 65521;
    }
    (b << 16) | a
}

/// A zlib stream of `raw` in stored (uncompressed) deflate blocks.
fn zlib_stored(raw: &[u8]) -> Vec<u8> {
    let mut z = vec![0x78, 0x01];
    let blocks: Vec<&[u8]> = if raw.is_empty() { vec![&[]] } else { raw.chunks(65_535).collect() };
    for (k, b) in blocks.iter().enumerate() {
        z.push(u8::from(k + 1 == blocks.len()));
        let len = b.len() as u16;
        z.extend_from_slice(&len.to_le_bytes());
        z.extend_from_slice(&(!len).to_le_bytes());
        z.extend_from_slice(b);
    }
    z.extend_from_slice(&adler32(raw).to_be_bytes());
    z
}

fn chunk(png: &mut Vec<u8>, kind: &[u8; 4], data: &[u8]) {
    png.extend_from_slice(&(data.len() as u32).to_be_bytes());
    let start = png.len();
    png.extend_from_slice(kind);
    png.extend_from_slice(data);
    let crc = crc32(&png[start..]);
    png.extend_from_slice(&crc.to_be_bytes());
}

/// A PNG of `w` x `h` RGBA pixels, row by row from the top.
pub(crate) fn png_rgba(w: usize, h: usize, rgba: &[[u8; 4]]) -> Vec<u8> {
    assert_eq!(rgba.len(), w * h, "one colour per pixel");
    let mut raw = Vec::with_capacity(h * (1 + 4 * w));
    for row in rgba.chunks(w.max(1)) {
        raw.push(0); // filter: none
        for p in row {
            raw.extend_from_slice(p);
        }
    }
    let mut png = vec![0x89, b'P', b'N', b'G', 0x0d, 0x0a, 0x1a, 0x0a];
    let mut ihdr = Vec::with_capacity(13);
    ihdr.extend_from_slice(&(w as u32).to_be_bytes());
    ihdr.extend_from_slice(&(h as u32).to_be_bytes());
    ihdr.extend_from_slice(&[8, 6, 0, 0, 0]); // 8 bits, RGBA, deflate, no filter set, no interlace
    chunk(&mut png, b"IHDR", &ihdr);
    chunk(&mut png, b"IDAT", &zlib_stored(&raw));
    chunk(&mut png, b"IEND", &[]);
    png
}

/// Standard base64 (RFC 4648, with padding).
pub(crate) fn base64(bytes: &[u8]) -> String {
    const A: &[u8; 64] = b"ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    let mut s = String::with_capacity(bytes.len().div_ceil(3) * 4);
    for c in bytes.chunks(3) {
        let n = (u32::from(c[0]) << 16)
            | (u32::from(*c.get(1).unwrap_or(&0)) << 8)
            | u32::from(*c.get(2).unwrap_or(&0));
        for k in 0..4 {
            if k <= c.len() {
                s.push(A[((n >> (18 - 6 * k)) & 63) as usize] as char);
            } else {
                s.push('=');
            }
        }
    }
    s
}

/// Replace the marker rectangle of `svg` by `<image>` of the PNG, stretched over the same
/// box (pixels drawn as squares, not blurred). An error if the marker is not found once.
pub(crate) fn embed(svg: &mut String, png: &[u8]) -> Result<(), String> {
    let fill = format!("fill=\"#{:02X}{:02X}{:02X}\"", MARKER.0, MARKER.1, MARKER.2);
    let at = svg
        .find(&fill)
        .or_else(|| svg.find(&fill.to_lowercase()))
        .ok_or("the map's image marker is missing")?;
    let start = svg[..at].rfind("<rect").ok_or("the marker is not a rectangle")?;
    let end = at + svg[at..].find("/>").ok_or("the marker rectangle is not closed")? + 2;
    let rect = &svg[start..end];
    let attr = |name: &str| -> Result<String, String> {
        let key = format!(" {name}=\"");
        let k = rect.find(&key).ok_or_else(|| format!("the marker has no {name}"))? + key.len();
        let v = &rect[k..];
        Ok(v[..v.find('"').ok_or("unterminated attribute")?].to_string())
    };
    let (x, y, w, h) = (attr("x")?, attr("y")?, attr("width")?, attr("height")?);
    let image = format!(
        "<image x=\"{x}\" y=\"{y}\" width=\"{w}\" height=\"{h}\" preserveAspectRatio=\"none\" \
         image-rendering=\"optimizeSpeed\" style=\"image-rendering:pixelated\" \
         href=\"data:image/png;base64,{}\"/>",
        base64(png)
    );
    svg.replace_range(start..end, &image);
    if svg.contains(&fill) {
        return Err("the map's image marker appears twice".to_string());
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn checksums_match_their_published_values() {
        // RFC 3720 / zlib test vectors: CRC-32 and Adler-32 of "123456789".
        assert_eq!(crc32(b"123456789"), 0xcbf4_3926);
        assert_eq!(adler32(b"123456789"), 0x091e_01de);
        // PNG's IEND chunk: its CRC is fixed by the format.
        assert_eq!(crc32(b"IEND"), 0xae42_6082);
    }

    #[test]
    fn base64_matches_rfc_4648() {
        for (i, o) in [
            ("", ""),
            ("f", "Zg=="),
            ("fo", "Zm8="),
            ("foo", "Zm9v"),
            ("foob", "Zm9vYg=="),
            ("fooba", "Zm9vYmE="),
            ("foobar", "Zm9vYmFy"),
        ] {
            assert_eq!(base64(i.as_bytes()), o, "{i}");
        }
    }

    #[test]
    fn stored_blocks_hold_the_bytes_and_split_at_64k() {
        let raw: Vec<u8> = (0..70_000u32).map(|k| (k % 251) as u8).collect();
        let z = zlib_stored(&raw);
        // header, two blocks of 5 + len bytes, adler.
        assert_eq!(z.len(), 2 + (5 + 65_535) + (5 + 4465) + 4);
        assert_eq!(z[2], 0, "first block not final");
        assert_eq!(&z[7..7 + 65_535], &raw[..65_535]);
        assert_eq!(z[7 + 65_535], 1, "second block final");
        let png = png_rgba(2, 1, &[[255, 0, 0, 255], [0, 0, 255, 0]]);
        assert_eq!(&png[..8], b"\x89PNG\r\n\x1a\n");
        assert_eq!(&png[png.len() - 12..], b"\0\0\0\0IEND\xaeB`\x82");
    }

    #[test]
    fn the_marker_is_replaced_by_the_image() {
        let mut svg = String::from(
            "<svg><rect x=\"10\" y=\"20\" width=\"30\" height=\"40\" opacity=\"1\" fill=\"#010203\" stroke=\"none\"/><path d=\"M0 0\"/></svg>",
        );
        embed(&mut svg, &png_rgba(1, 1, &[[0, 0, 0, 255]])).unwrap();
        assert!(svg.starts_with("<svg><image x=\"10\" y=\"20\" width=\"30\" height=\"40\" "));
        assert!(svg.contains("data:image/png;base64,iVBORw0KGgo"), "{svg}");
        assert!(svg.ends_with("<path d=\"M0 0\"/></svg>"));
        assert!(embed(&mut svg, &[]).is_err());
    }
}
