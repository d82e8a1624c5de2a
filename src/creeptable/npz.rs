//! NumPy's `.npy` and `.npz`, by hand: the few dozen lines a creep table needs (module docs of `creeptable`).
//!
//! `.npy` (NumPy's format, version 1.0): the magic `\x93NUMPY`, the version bytes 1, 0, the header's length (u16,
//! little-endian), the header — a Python dict literal `{'descr': '<f8', 'fortran_order': False, 'shape': (…), }`
//! padded with spaces and a newline so the data start at a multiple of 64 bytes — then the data, C order.
//! `.npz`: a ZIP archive (stored, no compression, no data descriptors, fixed 1980-01-01 time stamps so the same table
//! gives the same bytes) with one member `NAME.npy` per array. The reader takes what the writer writes (stored
//! members with their sizes in the local headers, npy versions 1 and 2) and refuses anything else by name.

use super::spec::Axes;
use super::table::CreepTable;
use crate::error::{Error, Result as IoResult};
use std::path::Path;

/// One array: its name, NumPy dtype (`<f8` or `|i1`), shape and little-endian bytes.
struct Array {
    name: &'static str,
    descr: &'static str,
    shape: Vec<usize>,
    data: Vec<u8>,
}

fn f8(name: &'static str, shape: Vec<usize>, values: &[f64]) -> Array {
    Array { name, descr: "<f8", shape, data: values.iter().flat_map(|x| x.to_le_bytes()).collect() }
}

/// An `.npy` file of one array.
fn npy(a: &Array) -> Vec<u8> {
    let shape = match a.shape.as_slice() {
        [n] => format!("({n},)"),
        s => format!("({})", s.iter().map(usize::to_string).collect::<Vec<_>>().join(", ")),
    };
    let mut header = format!("{{'descr': '{}', 'fortran_order': False, 'shape': {shape}, }}", a.descr);
    // 10 bytes of magic, version and length, then the header ending in '\n', the whole a multiple of 64.
    let total = (10 + header.len() + 1).div_ceil(64) * 64;
    header.push_str(&" ".repeat(total - 10 - header.len() - 1));
    header.push('\n');
    let mut out = Vec::with_capacity(total + a.data.len());
    out.extend_from_slice(b"\x93NUMPY\x01\x00");
    out.extend_from_slice(&(header.len() as u16).to_le_bytes());
    out.extend_from_slice(header.as_bytes());
    out.extend_from_slice(&a.data);
    out
}

/// CRC-32 (IEEE 802.3, reflected, as ZIP uses).
fn crc32(bytes: &[u8]) -> u32 {
    let mut crc = 0xFFFF_FFFFu32;
    for &b in bytes {
        crc ^= u32::from(b);
        for _ in 0..8 {
            crc = if crc & 1 != 0 { (crc >> 1) ^ 0xEDB8_8320 } else { crc >> 1 };
        }
    }
    !crc
}

/// A stored ZIP archive of named files.
fn zip(files: &[(String, Vec<u8>)]) -> Vec<u8> {
    let (mut out, mut central) = (Vec::new(), Vec::new());
    // Version 2.0, no flags, stored, time 00:00, date 1980-01-01.
    let common = |crc: u32, size: u32, name: &str| {
        let mut v = Vec::new();
        for x in [20u16, 0, 0, 0, 0x21] {
            v.extend_from_slice(&x.to_le_bytes());
        }
        for x in [crc, size, size] {
            v.extend_from_slice(&x.to_le_bytes());
        }
        v.extend_from_slice(&(name.len() as u16).to_le_bytes());
        v.extend_from_slice(&0u16.to_le_bytes());
        v
    };
    for (name, data) in files {
        let (crc, size, offset) = (crc32(data), data.len() as u32, out.len() as u32);
        out.extend_from_slice(&0x0403_4b50u32.to_le_bytes());
        out.extend_from_slice(&common(crc, size, name));
        out.extend_from_slice(name.as_bytes());
        out.extend_from_slice(data);
        central.extend_from_slice(&0x0201_4b50u32.to_le_bytes());
        central.extend_from_slice(&20u16.to_le_bytes());
        central.extend_from_slice(&common(crc, size, name));
        // Comment length, disk, internal and external attributes, the local header's offset.
        central.extend_from_slice(&[0u8; 10]);
        central.extend_from_slice(&offset.to_le_bytes());
        central.extend_from_slice(name.as_bytes());
    }
    let (cd_offset, cd_size, n) = (out.len() as u32, central.len() as u32, files.len() as u16);
    out.extend_from_slice(&central);
    out.extend_from_slice(&0x0605_4b50u32.to_le_bytes());
    for x in [0u16, 0, n, n] {
        out.extend_from_slice(&x.to_le_bytes());
    }
    out.extend_from_slice(&cd_size.to_le_bytes());
    out.extend_from_slice(&cd_offset.to_le_bytes());
    out.extend_from_slice(&0u16.to_le_bytes());
    out
}

impl CreepTable {
    /// Reads a table's `.npz` (as rollbem writes it: stored members, no ZIP64). Errors: the file cannot be read, a
    /// member is missing or not of the layout (its name and why).
    pub fn read_npz(path: &Path) -> IoResult<CreepTable> {
        let bytes = std::fs::read(path).map_err(|source| Error::Io { path: path.to_path_buf(), source })?;
        read_table(&bytes).map_err(|message| Error::Parse { path: path.to_path_buf(), message })
    }

    /// Writes the table as `.npz` (by the rules of `crate::io::write_output`: nothing half-written).
    pub fn write_npz(&self, path: &Path) -> IoResult<()> {
        crate::io::write_output_bytes(path, &write_table(self))
    }
}

/// The `.npz` bytes of a table.
pub(super) fn write_table(t: &CreepTable) -> Vec<u8> {
    let s = t.axes.shape();
    let arrays = [
        f8("forces", vec![s[0], s[1], s[2], s[3], s[4], 3], &t.forces),
        Array { name: "status", descr: "|i1", shape: s.to_vec(), data: t.status.iter().map(|&c| c as u8).collect() },
        f8("nu", vec![s[0]], &t.axes.nu),
        f8("a_over_b", vec![s[1]], &t.axes.a_over_b),
        f8("xi", vec![s[2]], &t.axes.xi),
        f8("eta", vec![s[3]], &t.axes.eta),
        f8("phi", vec![s[4]], &t.axes.phi),
        f8("coefficients", vec![s[0], s[1], 3], &t.coefficients),
    ];
    let files: Vec<(String, Vec<u8>)> = arrays.iter().map(|a| (format!("{}.npy", a.name), npy(a))).collect();
    zip(&files)
}

fn u16_at(b: &[u8], i: usize) -> Option<usize> {
    b.get(i..i + 2).map(|s| u16::from_le_bytes([s[0], s[1]]) as usize)
}

fn u32_at(b: &[u8], i: usize) -> Option<usize> {
    b.get(i..i + 4).map(|s| u32::from_le_bytes([s[0], s[1], s[2], s[3]]) as usize)
}

/// The members of a stored ZIP archive: (name, bytes).
fn unzip(b: &[u8]) -> Result<Vec<(String, &[u8])>, String> {
    let mut out = Vec::new();
    let mut i = 0;
    while u32_at(b, i) == Some(0x0403_4b50) {
        let field = |off: usize| u16_at(b, i + off).ok_or("a ZIP local header is cut short");
        let (flags, method) = (field(6)?, field(8)?);
        let size = u32_at(b, i + 18).ok_or("a ZIP local header is cut short")?;
        let (name_len, extra_len) = (field(26)?, field(28)?);
        let name_at = i + 30;
        let name = b.get(name_at..name_at + name_len).ok_or("a ZIP member's name is cut short")?;
        let name = String::from_utf8_lossy(name).into_owned();
        if method != 0 || flags & 0x8 != 0 || size == 0xFFFF_FFFF {
            return Err(format!("member {name}: compressed, streamed or ZIP64 (only stored members are read)"));
        }
        let data_at = name_at + name_len + extra_len;
        let data = b.get(data_at..data_at + size).ok_or_else(|| format!("member {name} is cut short"))?;
        if crc32(data) != u32_at(b, i + 14).unwrap_or(0) as u32 {
            return Err(format!("member {name}: CRC-32 does not match"));
        }
        out.push((name, data));
        i = data_at + size;
    }
    if out.is_empty() {
        return Err("not a ZIP archive (no local file header at its start)".into());
    }
    Ok(out)
}

/// An `.npy` member's dtype, shape and data.
fn parse_npy(b: &[u8]) -> Result<(String, Vec<usize>, &[u8]), String> {
    if b.get(..6) != Some(b"\x93NUMPY") {
        return Err("not an .npy array (no magic)".into());
    }
    let (len, start) = match b.get(6) {
        Some(1) => (u16_at(b, 8).ok_or("cut short")?, 10),
        Some(2) | Some(3) => (u32_at(b, 8).ok_or("cut short")?, 12),
        _ => return Err("unknown .npy version".into()),
    };
    let header =
        std::str::from_utf8(b.get(start..start + len).ok_or("header cut short")?).map_err(|e| e.to_string())?;
    let after = |key: &str| header.find(key).map(|i| &header[i + key.len()..]).ok_or(format!("no {key} in its header"));
    let descr = after("'descr':")?.trim_start().trim_start_matches('\'');
    let descr = descr.split('\'').next().unwrap_or("").to_string();
    if !after("'fortran_order':")?.trim_start().starts_with("False") {
        return Err("Fortran order (only C order is read)".into());
    }
    let shape = after("'shape':")?.trim_start().trim_start_matches('(');
    let shape = shape.split(')').next().unwrap_or("");
    let shape: Vec<usize> = shape
        .split(',')
        .map(str::trim)
        .filter(|s| !s.is_empty())
        .map(|s| s.parse().map_err(|_| format!("shape entry {s:?}")))
        .collect::<Result<_, _>>()?;
    Ok((descr, shape, &b[start + len..]))
}

/// A table from its `.npz` bytes.
pub(super) fn read_table(bytes: &[u8]) -> Result<CreepTable, String> {
    let members = unzip(bytes)?;
    let get = |name: &str, descr: &str| -> Result<(Vec<usize>, &[u8]), String> {
        let file = format!("{name}.npy");
        let (_, data) = members.iter().find(|(n, _)| *n == file).ok_or(format!("no member {file}"))?;
        let (d, shape, data) = parse_npy(data).map_err(|m| format!("{file}: {m}"))?;
        if d != descr {
            return Err(format!("{file}: dtype {d}, expected {descr}"));
        }
        let width = if descr == "<f8" { 8 } else { 1 };
        if data.len() != shape.iter().product::<usize>() * width {
            return Err(format!("{file}: {} bytes of data for shape {shape:?}", data.len()));
        }
        Ok((shape, data))
    };
    let floats = |name: &str| -> Result<(Vec<usize>, Vec<f64>), String> {
        let (shape, data) = get(name, "<f8")?;
        let v = data.chunks_exact(8).map(|c| f64::from_le_bytes(c.try_into().unwrap_or([0; 8]))).collect();
        Ok((shape, v))
    };
    let axis = |name: &str| floats(name).map(|(_, v)| v);
    let axes =
        Axes { nu: axis("nu")?, a_over_b: axis("a_over_b")?, xi: axis("xi")?, eta: axis("eta")?, phi: axis("phi")? };
    let s = axes.shape();
    let (fshape, forces) = floats("forces")?;
    let (sshape, status) = get("status", "|i1")?;
    let (cshape, coefficients) = floats("coefficients")?;
    if fshape != [s[0], s[1], s[2], s[3], s[4], 3] || sshape != s || cshape != [s[0], s[1], 3] {
        return Err(format!("shapes {fshape:?}, {sshape:?}, {cshape:?} do not match the axes' {s:?}"));
    }
    Ok(CreepTable { axes, forces, status: status.iter().map(|&c| c as i8).collect(), coefficients })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn crc32_of_the_check_string() {
        // Expected: the CRC-32 check value of "123456789", 0xCBF43926 (the standard's test vector).
        assert_eq!(crc32(b"123456789"), 0xCBF4_3926);
    }

    #[test]
    fn npy_header_is_64_aligned_and_numpy_shaped() {
        // Expected (NumPy's format spec, version 1.0): the data start at a multiple of 64, the header ends in '\n',
        // and a 1-D shape is written with its trailing comma.
        let a = f8("x", vec![3], &[1.0, 2.0, 3.0]);
        let b = npy(&a);
        assert_eq!((b.len() - 24) % 64, 0);
        let len = u16_at(&b, 8).unwrap();
        assert_eq!(b[10 + len - 1], b'\n');
        let header = std::str::from_utf8(&b[10..10 + len]).unwrap();
        assert!(header.starts_with("{'descr': '<f8', 'fortran_order': False, 'shape': (3,), }"), "{header}");
        let (d, shape, data) = parse_npy(&b).unwrap();
        assert_eq!((d.as_str(), shape, data.len()), ("<f8", vec![3], 24));
    }

    #[test]
    fn a_corrupted_member_is_refused() {
        let t = CreepTable {
            axes: Axes { nu: vec![0.25], a_over_b: vec![1.0], xi: vec![0.0], eta: vec![0.0], phi: vec![0.0] },
            forces: vec![0.0, 0.0, 0.0],
            status: vec![0],
            coefficients: vec![1.0, 2.0, 3.0],
        };
        let mut b = write_table(&t);
        assert_eq!(read_table(&b).unwrap(), t);
        let at = b.len() / 3;
        b[at] ^= 0xFF;
        assert!(read_table(&b).is_err());
    }
}
