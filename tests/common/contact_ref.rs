//! Reading CONTACT's reference data (`reference/contact3d/`, written by `benches/peer/contact_ref3d.py` and
//! `reference/contact3d/fastsim/extract.py`) in the tests that compare with it.
#![allow(dead_code)]

use std::collections::HashMap;

/// One CSV of `reference/contact3d/` (`name` may start with a sub-folder, `fastsim/...`) as rows of column → text.
pub fn csv(name: &str) -> Vec<HashMap<String, String>> {
    let path = format!("{}/reference/contact3d/{name}", env!("CARGO_MANIFEST_DIR"));
    let mut r = csv::Reader::from_path(&path).unwrap_or_else(|e| panic!("{path}: {e}"));
    let head: Vec<String> = r.headers().unwrap().iter().map(String::from).collect();
    r.records().map(|rec| head.iter().cloned().zip(rec.unwrap().iter().map(String::from)).collect()).collect()
}

/// A cell as a number (panics naming the column).
pub fn num(row: &HashMap<String, String>, key: &str) -> f64 {
    row[key].trim().parse().unwrap_or_else(|_| panic!("{key} = {:?}", row[key]))
}

/// Half a unit of the last digit of a number as CONTACT prints it ("-1.505E+04": 5; "0.000": 5e-4; "1629.": 0.5;
/// "0.493738E-04": 5e-11).
pub fn half_unit(printed: &str) -> f64 {
    let s = printed.trim();
    let (mantissa, exp) = match s.find(['E', 'e']) {
        Some(k) => (&s[..k], s[k + 1..].parse::<i32>().unwrap()),
        None => (s, 0),
    };
    let decimals = mantissa.find('.').map_or(0, |k| mantissa.len() - k - 1) as i32;
    0.5 * 10f64.powi(exp - decimals)
}
