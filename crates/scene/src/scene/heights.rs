//! Reading a measured surface: heights on a lattice from a `.npy` file (little-endian
//! float64 or float32, C order, two dimensions (ny, nx)) or a `.csv` file (one row per y,
//! comma- or whitespace-separated numbers; lines starting with `#` are skipped). The values
//! are returned row by row (index `j * nx + i`); the caller checks the shape against the
//! scene's `cells` and applies the unit.

use std::path::Path;

/// Read `name` (relative to the directory of `scene_file` when given). Errors are messages
/// naming the file and what is wrong.
pub(crate) fn read(name: &str, scene_file: Option<&Path>) -> Result<Vec<f64>, String> {
    let path = match scene_file.and_then(Path::parent) {
        Some(dir) if Path::new(name).is_relative() => dir.join(name),
        _ => Path::new(name).to_path_buf(),
    };
    let bytes = std::fs::read(&path).map_err(|e| format!("cannot read {}: {e}", path.display()))?;
    let ext = path.extension().and_then(|e| e.to_str()).unwrap_or("").to_ascii_lowercase();
    match ext.as_str() {
        "npy" => npy(&bytes).map_err(|m| format!("{}: {m}", path.display())),
        "csv" | "txt" => csv(&bytes).map_err(|m| format!("{}: {m}", path.display())),
        _ => Err(format!("{}: unknown format (expected .npy or .csv)", path.display())),
    }
}

fn npy(b: &[u8]) -> Result<Vec<f64>, String> {
    if b.len() < 10 || &b[..6] != b"\x93NUMPY" {
        return Err("not a .npy file (no NUMPY magic)".to_string());
    }
    let (hlen, start) = match b[6] {
        1 => (u16::from_le_bytes([b[8], b[9]]) as usize, 10),
        2 | 3 if b.len() >= 12 => (u32::from_le_bytes([b[8], b[9], b[10], b[11]]) as usize, 12),
        v => return Err(format!(".npy version {v} is not supported")),
    };
    let header = std::str::from_utf8(b.get(start..start + hlen).ok_or("truncated header")?)
        .map_err(|_| "the header is not text".to_string())?;
    if header.contains("'fortran_order': True") {
        return Err("Fortran-ordered arrays are not supported; save in C order".to_string());
    }
    let width = if header.contains("'<f8'") {
        8
    } else if header.contains("'<f4'") {
        4
    } else {
        return Err(
            "the data type must be little-endian float64 ('<f8') or float32 ('<f4')".to_string()
        );
    };
    let shape = header
        .split("'shape':")
        .nth(1)
        .and_then(|s| s.split('(').nth(1))
        .and_then(|s| s.split(')').next())
        .ok_or("no shape in the header")?;
    let dims: Vec<usize> = shape
        .split(',')
        .filter(|t| !t.trim().is_empty())
        .map(|t| t.trim().parse().unwrap_or(0))
        .collect();
    if dims.len() != 2 {
        return Err(format!("expected a two-dimensional array (ny, nx), found shape ({shape})"));
    }
    let n = dims[0] * dims[1];
    let data = &b[start + hlen..];
    if data.len() != n * width {
        return Err(format!("{} bytes of data for shape ({shape})", data.len()));
    }
    Ok(data
        .chunks_exact(width)
        .map(|c| match width {
            8 => f64::from_le_bytes(c.try_into().unwrap_or([0; 8])),
            _ => f64::from(f32::from_le_bytes(c.try_into().unwrap_or([0; 4]))),
        })
        .collect())
}

fn csv(b: &[u8]) -> Result<Vec<f64>, String> {
    let text = std::str::from_utf8(b).map_err(|_| "not text".to_string())?;
    let mut out = Vec::new();
    let mut width = None;
    for (line_no, line) in text.lines().enumerate() {
        let line = line.trim();
        if line.is_empty() || line.starts_with('#') {
            continue;
        }
        let row: Vec<f64> = line
            .split(|c: char| c == ',' || c.is_whitespace())
            .filter(|t| !t.is_empty())
            .map(|t| {
                t.parse::<f64>().map_err(|_| format!("line {}: `{t}` is not a number", line_no + 1))
            })
            .collect::<Result<_, _>>()?;
        match width {
            None => width = Some(row.len()),
            Some(w) if w != row.len() => {
                return Err(format!(
                    "line {}: {} values, the first row has {w}",
                    line_no + 1,
                    row.len()
                ))
            }
            _ => {}
        }
        out.extend(row);
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A float64 `.npy` file (version 1.0, C order) as NumPy's `np.save` writes it: magic,
    /// header length, the header padded with spaces to a multiple of 64 bytes, the data.
    fn npy_file(data: &[f64], shape: &str) -> Vec<u8> {
        let mut header = format!("{{'descr': '<f8', 'fortran_order': False, 'shape': {shape}, }}");
        while (10 + header.len() + 1) % 64 != 0 {
            header.push(' ');
        }
        header.push('\n');
        let mut out = b"\x93NUMPY\x01\x00".to_vec();
        out.extend_from_slice(&(header.len() as u16).to_le_bytes());
        out.extend_from_slice(header.as_bytes());
        data.iter().for_each(|v| out.extend_from_slice(&v.to_le_bytes()));
        out
    }

    #[test]
    fn npy_of_two_dimensions_reads_back() {
        let data: Vec<f64> = (0..12).map(|k| k as f64 * 0.5 - 1.0).collect();
        assert_eq!(npy(&npy_file(&data, "(3, 4)")).unwrap(), data);
        assert!(npy(&npy_file(&data, "(12,)")).is_err(), "one dimension is refused");
    }

    #[test]
    fn csv_rows_are_read_in_order_and_ragged_rows_refused() {
        assert_eq!(
            csv(b"# heights\n1, 2, 3\n4 5 6\n").unwrap(),
            vec![1.0, 2.0, 3.0, 4.0, 5.0, 6.0]
        );
        assert!(csv(b"1,2\n3\n").unwrap_err().contains("line 2"));
        assert!(csv(b"1,x\n").unwrap_err().contains("not a number"));
    }
}
