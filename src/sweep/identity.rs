//! What a sweep's files were written for: the **identity** of the resolved cases, so that `--resume` and
//! `sweep-merge --spec` never mix rows of other cases with this sweep's (issue 31).
//!
//! Two marks, one per file and one per row:
//! - **Per row, `scene_digest`**: the digest of the case's resolved scene — its document as validated, every key
//!   of the base scene with the swept values set and the defaults filled in, serialized as JSON (the form a result
//!   document embeds) — hashed with FNV-1a (64 bits, written `fnv1a64:` and 16 hex digits). Two rows of the same
//!   case of the same base scene and spec carry the same digest whichever run, shard or machine wrote them; a case
//!   whose base scene, swept values or solver settings changed carries another. A finished CSV carries it in every
//!   row, so a resume from it (or a merge with `--spec`) checks every case it holds against the spec as it is now.
//! - **Per journal, an [`Identity`] line** under the journal's first line: the rollbem version, the spec's name, the
//!   shard, `warm_start` and `timing_repeats` (both change what the rows hold), every grid (its base scene as written
//!   in the spec and its keys with their values), every base scene's document as read (every key, as written), the
//!   number of cases, and `resolved`, a running digest over every case's `scene_digest` in case order (all shards').
//!   A resume compares it with the sweep's before it reads a row, and names what changed: the version, the name,
//!   the shard, a swept key, a key of a base scene (with its old and new values). `resolved` catches the rest (a
//!   change of rollbem that resolves the same documents into other scenes without a new version number is not
//!   caught: only the document is digested, not rollbem's code).
//!
//! FNV-1a is not a cryptographic hash: it finds changes, not forgeries. It is written here (a dozen lines) so that a
//! digest does not change with the Rust release or a dependency: a journal written by one build is read by the next.
//! Memory: the digests are computed case by case as the cases are validated and folded as they go; nothing is kept
//! per case.

use crate::scene::{AnyScene, Scene};
use serde::{Deserialize, Serialize};
use std::collections::{BTreeMap, BTreeSet};
use toml::{Table, Value};

/// The start of a journal's identity line (its second line).
pub const IDENTITY_PREFIX: &str = "# identity ";

/// FNV-1a (64 bits), fed by [`std::io::Write`] (so a serializer writes into it without a buffer).
#[derive(Debug, Clone, Copy)]
pub struct Fnv(u64);

impl Default for Fnv {
    fn default() -> Fnv {
        Fnv(0xcbf2_9ce4_8422_2325)
    }
}

impl Fnv {
    /// Feed bytes.
    pub fn eat(&mut self, bytes: &[u8]) {
        for &b in bytes {
            self.0 = (self.0 ^ u64::from(b)).wrapping_mul(0x0000_0100_0000_01b3);
        }
    }

    /// The digest of what was fed.
    pub fn digest(self) -> u64 {
        self.0
    }
}

impl std::io::Write for Fnv {
    fn write(&mut self, buf: &[u8]) -> std::io::Result<usize> {
        self.eat(buf);
        Ok(buf.len())
    }
    fn flush(&mut self) -> std::io::Result<()> {
        Ok(())
    }
}

/// The digest of a resolved scene: FNV-1a of its document as JSON (see the module docs). Where it is written
/// from does not enter (a scene's origin is not part of its document).
pub fn scene_digest(scene: &Scene) -> u64 {
    let mut h = Fnv::default();
    // Writing into the hasher cannot fail, and a scene's document always serializes (result documents embed it); an
    // error would leave a digest of what was written so far, which still differs from a complete one's.
    let _ = serde_json::to_writer(&mut h, scene);
    h.digest()
}

/// The digest of a resolved scene of either kind: a 2D scene's [`scene_digest`]; a 3D scene's FNV-1a of its
/// document as validated (defaults filled in) as JSON. A 3D scene's `gap_file` enters by its name, not its content.
pub fn case_digest(scene: &AnyScene) -> u64 {
    match scene {
        AnyScene::Plane(s) => scene_digest(s),
        AnyScene::Space(s) => {
            let mut h = Fnv::default();
            // As in `scene_digest`: writing into the hasher cannot fail.
            let _ = serde_json::to_writer(&mut h, s.document());
            h.digest()
        }
    }
}

/// A digest as written in the CSV and the journal: `fnv1a64:` and 16 hex digits (a prefix, so that no reader takes
/// it for a number).
pub fn show_digest(d: u64) -> String {
    format!("fnv1a64:{d:016x}")
}

/// A digest read back from [`show_digest`]'s form.
pub fn parse_digest(s: &str) -> Option<u64> {
    let hex = s.strip_prefix("fnv1a64:")?;
    if hex.len() != 16 {
        return None;
    }
    u64::from_str_radix(hex, 16).ok()
}

/// One case's mark in an order-free sum over a set of cases: the sum (wrapping) of `mark(case, digest)` over the
/// cases of a file equals the sum over the same cases computed from the spec only if (barring a 2⁻⁶⁴ accident)
/// every case has the same digest in both, whatever order the file holds them in.
pub fn mark(case: usize, digest: u64) -> u64 {
    let mut h = Fnv::default();
    h.eat(&(case as u64).to_le_bytes());
    h.eat(&digest.to_le_bytes());
    h.digest()
}

/// A running digest over the cases' digests, in case order.
#[derive(Debug, Clone, Copy, Default)]
pub struct Running(Fnv);

impl Running {
    /// Add the next case's digest.
    pub fn add(&mut self, digest: u64) {
        self.0.eat(&digest.to_le_bytes());
    }

    /// The digest so far.
    pub fn digest(&self) -> u64 {
        self.0.digest()
    }
}

/// One grid of a sweep as [`Identity::new`] takes it: its base scene as written in the spec, that scene's document,
/// and its (possibly zipped) keys with their values.
pub type GridParts<'a> = (String, &'a Table, &'a [(String, Vec<Value>)]);

/// One grid of a sweep, as its identity records it.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct GridIdentity {
    /// Its base scene, as written in the spec.
    pub base: String,
    /// Its (possibly zipped) keys, each with the array of its values.
    pub keys: BTreeMap<String, serde_json::Value>,
}

/// What a journal was written for (see the module docs). Written on the journal's second line as JSON.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Identity {
    /// The version of rollbem that wrote it.
    pub rollbem: String,
    /// The spec's `name`.
    pub spec: String,
    /// The shard (`k/n`), or none for the whole sweep.
    pub shard: Option<String>,
    /// The spec's `warm_start`.
    pub warm_start: bool,
    /// The spec's `timing_repeats`.
    pub timing_repeats: usize,
    /// The grids, in the spec's order.
    pub grids: Vec<GridIdentity>,
    /// Every base scene (as written in the spec) with its document as read (every key as written).
    pub bases: BTreeMap<String, serde_json::Value>,
    /// The number of cases (all shards').
    pub cases: usize,
    /// The running digest over every case's resolved scene, in case order ([`show_digest`]'s form).
    pub resolved: String,
}

/// A TOML value or table as JSON (the identity's form; TOML's values all have one, a date as an object).
fn json<T: Serialize + ?Sized>(v: &T) -> serde_json::Value {
    serde_json::to_value(v).unwrap_or(serde_json::Value::Null)
}

/// A value in a message: JSON, cut at 60 characters.
fn brief(v: Option<&serde_json::Value>) -> String {
    let Some(v) = v else { return "(absent)".into() };
    let s = v.to_string();
    match s.char_indices().nth(60) {
        Some((i, _)) => format!("{}…", &s[..i]),
        None => s,
    }
}

/// The dotted keys at which two documents differ (tables compared key by key, anything else as a whole).
fn changed_keys(prefix: &str, old: &serde_json::Value, new: &serde_json::Value, out: &mut Vec<String>) {
    use serde_json::Value as J;
    match (old, new) {
        (J::Object(a), J::Object(b)) => {
            let keys: BTreeSet<&String> = a.keys().chain(b.keys()).collect();
            for k in keys {
                let path = if prefix.is_empty() { k.clone() } else { format!("{prefix}.{k}") };
                match (a.get(k), b.get(k)) {
                    (Some(x), Some(y)) => changed_keys(&path, x, y, out),
                    (x, y) => out.push(format!("`{path}` {} → {}", brief(x), brief(y))),
                }
            }
        }
        (a, b) if a != b => out.push(format!("`{prefix}` {} → {}", brief(Some(a)), brief(Some(b)))),
        _ => {}
    }
}

/// `what` with at most the first five of `items`, and how many more.
fn listed(what: String, items: &[String]) -> String {
    let more = items.len().saturating_sub(5);
    let mut s = format!("{what}: {}", items[..items.len().min(5)].join(", "));
    if more > 0 {
        s += &format!(" and {more} more");
    }
    s
}

impl Identity {
    /// The identity of a sweep from its parts (`resolved` empty until the cases are digested).
    pub fn new(spec: &super::SweepSpec, shard: Option<super::Shard>, grids: &[GridParts<'_>]) -> Identity {
        let mut bases = BTreeMap::new();
        let mut out = Vec::with_capacity(grids.len());
        for (base, doc, entries) in grids {
            bases.entry(base.clone()).or_insert_with(|| json(*doc));
            let keys = entries.iter().map(|(k, a)| (k.clone(), json(a))).collect();
            out.push(GridIdentity { base: base.clone(), keys });
        }
        Identity {
            rollbem: env!("CARGO_PKG_VERSION").to_string(),
            spec: spec.name.clone(),
            shard: shard.map(|s| s.to_string()),
            warm_start: spec.warm_start,
            timing_repeats: spec.timing_repeats,
            cases: spec.len(),
            grids: out,
            bases,
            resolved: String::new(),
        }
    }

    /// The journal's identity line (with the line break).
    pub fn line(&self) -> String {
        // Serializing plain data into a string cannot fail.
        format!("{IDENTITY_PREFIX}{}\n", serde_json::to_string(self).unwrap_or_default())
    }

    /// Read an identity line (without its line break); `Err` says why it does not read.
    pub fn from_line(line: &str) -> std::result::Result<Identity, String> {
        let json = line.strip_prefix(IDENTITY_PREFIX).ok_or("its second line is not an identity line")?;
        serde_json::from_str(json.trim_end()).map_err(|e| format!("its identity line does not read: {e}"))
    }

    /// What differs between the identity a file was written for (`self`) and this sweep's (`now`), in words,
    /// `resolved` aside (it is known only once every case is validated: [`Identity::resolved_differs`]). Empty when
    /// nothing does.
    pub fn differences(&self, now: &Identity) -> Vec<String> {
        let mut out = Vec::new();
        if self.rollbem != now.rollbem {
            out.push(format!("it was written by rollbem {}, this is rollbem {}", self.rollbem, now.rollbem));
        }
        if self.spec != now.spec {
            out.push(format!("the spec's name was `{}`, it is `{}` now", self.spec, now.spec));
        }
        if self.shard != now.shard {
            let of = |s: &Option<String>| s.as_ref().map_or("the whole sweep".into(), |s| format!("shard {s}"));
            out.push(format!("it was written for {}, this run is {}", of(&self.shard), of(&now.shard)));
        }
        if self.warm_start != now.warm_start {
            out.push(format!("`warm_start` was {}, it is {} now", self.warm_start, now.warm_start));
        }
        if self.timing_repeats != now.timing_repeats {
            out.push(format!("`timing_repeats` was {}, it is {} now", self.timing_repeats, now.timing_repeats));
        }
        self.grid_differences(now, &mut out);
        for (path, doc) in &now.bases {
            let mut keys = Vec::new();
            match self.bases.get(path) {
                Some(old) => changed_keys("", old, doc, &mut keys),
                None => continue,
            }
            if !keys.is_empty() {
                out.push(listed(format!("the base scene {path} changed"), &keys));
            }
        }
        if out.is_empty() && self.cases != now.cases {
            out.push(format!("the spec had {} cases, it has {} now", self.cases, now.cases));
        }
        out
    }

    fn grid_differences(&self, now: &Identity, out: &mut Vec<String>) {
        if self.grids.len() != now.grids.len() {
            out.push(format!("the spec had {} grids, it has {} now", self.grids.len(), now.grids.len()));
        }
        for (i, (a, b)) in self.grids.iter().zip(&now.grids).enumerate() {
            if a.base != b.base {
                out.push(format!("grid {}'s base scene was {}, it is {} now", i + 1, a.base, b.base));
            }
            let keys: BTreeSet<&String> = a.keys.keys().chain(b.keys.keys()).collect();
            let changed: Vec<String> = keys
                .into_iter()
                .filter(|k| a.keys.get(*k) != b.keys.get(*k))
                .map(|k| format!("`{k}` {} → {}", brief(a.keys.get(k)), brief(b.keys.get(k))))
                .collect();
            if !changed.is_empty() {
                out.push(listed(format!("grid {}'s swept values changed", i + 1), &changed));
            }
        }
    }

    /// Whether the running digest over the resolved cases differs, in words (`now` with its `resolved` set).
    pub fn resolved_differs(&self, now: &Identity) -> Option<String> {
        (self.resolved != now.resolved).then(|| {
            format!(
                "its cases resolved to other scenes than they do now (digest {} then, {} now), though the spec and \
                 its base scenes read the same: rollbem resolves them otherwise (its defaults or its validation \
                 changed)",
                self.resolved, now.resolved
            )
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn fnv1a64_matches_the_published_vectors() {
        // The reference values of FNV-1a 64 (Fowler, Noll, Vo; draft-eastlake-fnv, test vectors).
        for (text, want) in
            [("", 0xcbf2_9ce4_8422_2325u64), ("a", 0xaf63_dc4c_8601_ec8c), ("foobar", 0x8594_4171_f739_67e8)]
        {
            let mut h = Fnv::default();
            h.eat(text.as_bytes());
            assert_eq!(h.digest(), want, "{text:?}");
        }
    }

    #[test]
    fn a_digest_reads_back_and_nothing_else_does() {
        for d in [0, 1, u64::MAX, 0x0123_4567_89ab_cdef] {
            assert_eq!(parse_digest(&show_digest(d)), Some(d));
        }
        for bad in ["", "0123456789abcdef", "fnv1a64:123", "fnv1a64:0123456789abcdeg", "fnv1a64:0123456789abcdef0"] {
            assert_eq!(parse_digest(bad), None, "{bad}");
        }
    }

    #[test]
    fn changed_keys_are_named_with_their_values() {
        let old = serde_json::json!({"wheel": {"poisson_ratio": 0.3, "radius": 460.0}, "name": "a"});
        let new = serde_json::json!({"wheel": {"poisson_ratio": 0.31, "radius": 460.0}, "name": "a", "x": 1});
        let mut out = Vec::new();
        changed_keys("", &old, &new, &mut out);
        assert_eq!(out, vec!["`wheel.poisson_ratio` 0.3 → 0.31".to_string(), "`x` (absent) → 1".to_string()]);
    }
}
