//! The report's pages and files: the problem families a detail page is written for, links made relative to the
//! page that holds them, and the manifest of the files one run wrote, with the removal of the files a previous run
//! left that this one did not write.

use crate::error::{Error, Result};
use std::collections::BTreeSet;
use std::path::{Path, PathBuf};

/// A problem family: one detail page under `families/`, one group of rows on the front page.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord)]
pub enum Family {
    /// Frictionless normal contact against Hertz (2D), and the finite wheel against the half-plane.
    Hertz,
    /// Partial slip under a tangential load against Cattaneo–Mindlin (2D).
    Cattaneo,
    /// Steady rolling against Carter: creep curves.
    Carter,
    /// Load paths: Mindlin–Deresiewicz loops, Spence's indentation, rolling from rest.
    Paths,
    /// Subsurface stresses.
    Stresses,
    /// The 3D half-space: Hertz's ellipse, Cattaneo–Mindlin, Coulomb's disc against the pyramid.
    Space3d,
    /// The seed paper's figures and its rolling formulation against steady rolling.
    Seed,
}

impl Family {
    /// The page's file name stem (`families/STEM.md`).
    pub fn slug(self) -> &'static str {
        match self {
            Family::Hertz => "hertz",
            Family::Cattaneo => "cattaneo-mindlin",
            Family::Carter => "carter",
            Family::Paths => "load-paths",
            Family::Stresses => "stresses",
            Family::Space3d => "half-space-3d",
            Family::Seed => "seed",
        }
    }

    /// The page's title.
    pub fn title(self) -> &'static str {
        match self {
            Family::Hertz => "Hertz: frictionless normal contact (2D)",
            Family::Cattaneo => "Cattaneo–Mindlin: partial slip under a tangential load (2D)",
            Family::Carter => "Carter: steady rolling and creep curves (2D)",
            Family::Paths => "Load paths",
            Family::Stresses => "Subsurface stresses",
            Family::Space3d => "3D half-space",
            Family::Seed => "The seed paper's figures and rolling formulation",
        }
    }

    /// A short name for the front page's tables.
    pub fn short(self) -> &'static str {
        match self {
            Family::Hertz => "Hertz",
            Family::Cattaneo => "Cattaneo–Mindlin",
            Family::Carter => "Carter",
            Family::Paths => "load paths",
            Family::Stresses => "stresses",
            Family::Space3d => "3D half-space",
            Family::Seed => "seed paper",
        }
    }

    /// The page's path relative to the report folder.
    pub fn page(self) -> String {
        format!("families/{}.md", self.slug())
    }
}

/// Markdown written as if it sat at the report folder's root, made right for a page `depth` folders below it: every
/// relative link target (`](figures/x.svg)`, `](methods.md#…)`) gets `../` per level. Absolute addresses, anchors
/// within the page and targets already starting with `../` are left alone.
pub fn relink(md: &str, depth: usize) -> String {
    if depth == 0 {
        return md.to_string();
    }
    let up = "../".repeat(depth);
    let mut out = String::with_capacity(md.len() + 64);
    let mut rest = md;
    while let Some(i) = rest.find("](") {
        out.push_str(&rest[..i + 2]);
        rest = &rest[i + 2..];
        let absolute = rest.starts_with("http://") || rest.starts_with("https://") || rest.starts_with('/');
        if !(absolute || rest.starts_with('#') || rest.starts_with("../")) {
            out.push_str(&up);
        }
    }
    out.push_str(rest);
    out
}

/// Files the report reads from its output folder and never removes: the peer tables the scripts of
/// `benches/peer/` write there (`run.sh`, `contact.sh`, `contact3d.sh`), run separately from `report`.
pub const DECLARED_INPUTS: [&str; 5] =
    ["peer-lcp.md", "peer-contact.md", "peer-contact3d.md", "peer-contact3d-rolling.md", "peer-contact3d-examples.md"];

/// The sub-folders the report owns: every file in them that a run did not write is removed by [`clean`].
pub const OWNED_FOLDERS: [&str; 6] = ["runs", "sweeps", "figures", "families", "peers", "html"];

/// The manifest's file name (in the output folder): every file the last run wrote, one relative path a line.
pub const MANIFEST: &str = "MANIFEST";

/// The files one run wrote, relative to the output folder.
#[derive(Debug, Default, Clone)]
pub struct Manifest {
    files: BTreeSet<PathBuf>,
}

impl Manifest {
    /// Record a file, given relative to the output folder or as a path under `out`.
    pub fn add(&mut self, out: &Path, file: impl AsRef<Path>) {
        let f = file.as_ref();
        let rel = f.strip_prefix(out).unwrap_or(f);
        self.files.insert(rel.to_path_buf());
    }

    /// Whether a relative path was recorded.
    pub fn contains(&self, rel: &Path) -> bool {
        self.files.contains(rel)
    }

    /// The manifest's text: the recorded paths, one a line, `/`-separated, sorted.
    pub fn text(&self) -> String {
        self.files.iter().map(|p| format!("{}\n", p.to_string_lossy().replace('\\', "/"))).collect()
    }
}

/// What [`clean`] did.
#[derive(Debug, Default)]
pub struct Cleaned {
    /// Files (and symbolic links) removed, relative to the output folder.
    pub removed: Vec<PathBuf>,
    /// Files at the folder's top level not written by this run, not declared inputs and not in the previous
    /// manifest: left in place (the report does not know them) and listed.
    pub unknown: Vec<PathBuf>,
}

/// Remove what a previous run left in `out` that this run did not write (`written`): every file or symbolic link
/// in the [`OWNED_FOLDERS`] (at any depth), and every top-level file the previous run's manifest (`previous`, the
/// paths it listed) names. Top-level files neither written nor listed are reported in [`Cleaned::unknown`], not
/// removed (a folder given as `--out` may hold a user's files), and [`DECLARED_INPUTS`] are kept. Safe by
/// construction: it only visits entries it lists in `out` and in real sub-folders of it (`DirEntry::file_type`
/// does not follow symbolic links: a link is removed as a link, never entered or followed, so nothing outside
/// `out` is touched), and it removes folders only when they are left empty.
pub fn clean(out: &Path, written: &Manifest, previous: &BTreeSet<PathBuf>) -> Result<Cleaned> {
    let mut done = Cleaned::default();
    for entry in read_dir(out)? {
        let (path, kind) = entry;
        let rel = PathBuf::from(path.file_name().expect("a directory entry has a name"));
        let name = rel.to_string_lossy().to_string();
        if kind.is_dir() {
            if OWNED_FOLDERS.contains(&name.as_str()) {
                clean_owned(out, &path, written, &mut done)?;
            }
            continue;
        }
        if written.contains(&rel) || DECLARED_INPUTS.contains(&name.as_str()) || name == MANIFEST {
            continue;
        }
        if previous.contains(&rel) {
            remove(&path, &rel, &mut done)?;
        } else {
            done.unknown.push(rel);
        }
    }
    Ok(done)
}

/// The entries of a folder with their own types (symbolic links not followed), sorted.
fn read_dir(dir: &Path) -> Result<Vec<(PathBuf, std::fs::FileType)>> {
    let io = |source| Error::Io { path: dir.to_path_buf(), source };
    let mut v = Vec::new();
    for e in std::fs::read_dir(dir).map_err(io)? {
        let e = e.map_err(io)?;
        v.push((e.path(), e.file_type().map_err(io)?));
    }
    v.sort_by(|a, b| a.0.cmp(&b.0));
    Ok(v)
}

/// Clean one owned folder (recursively, through real folders only).
fn clean_owned(out: &Path, dir: &Path, written: &Manifest, done: &mut Cleaned) -> Result<()> {
    for (path, kind) in read_dir(dir)? {
        let rel = path.strip_prefix(out).expect("visited under out").to_path_buf();
        if kind.is_dir() {
            clean_owned(out, &path, written, done)?;
            if std::fs::read_dir(&path).map(|mut d| d.next().is_none()).unwrap_or(false) {
                std::fs::remove_dir(&path).map_err(|source| Error::Write { path: path.clone(), source })?;
            }
        } else if !written.contains(&rel) {
            remove(&path, &rel, done)?;
        }
    }
    Ok(())
}

fn remove(path: &Path, rel: &Path, done: &mut Cleaned) -> Result<()> {
    std::fs::remove_file(path).map_err(|source| Error::Write { path: path.to_path_buf(), source })?;
    done.removed.push(rel.to_path_buf());
    Ok(())
}

/// The paths a previous run's manifest lists (empty when there is none).
pub fn previous_manifest(out: &Path) -> BTreeSet<PathBuf> {
    std::fs::read_to_string(out.join(MANIFEST))
        .map(|t| t.lines().filter(|l| !l.is_empty()).map(PathBuf::from).collect())
        .unwrap_or_default()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn links_are_made_relative_to_the_page() {
        let md = "![f](figures/a.svg) [m](methods.md#x) [w](https://x.org) [s](#here) [u](../up.md)";
        assert_eq!(
            relink(md, 1),
            "![f](../figures/a.svg) [m](../methods.md#x) [w](https://x.org) [s](#here) [u](../up.md)"
        );
        assert_eq!(relink(md, 0), md);
    }

    fn touch(p: &Path) {
        std::fs::create_dir_all(p.parent().unwrap()).unwrap();
        std::fs::write(p, "x").unwrap();
    }

    /// A stale file planted in an owned folder is removed; written files, declared inputs, a user's unknown
    /// top-level file stay; a top-level file the previous manifest lists is removed; a symbolic link to a folder
    /// outside is removed as a link, and the folder and its file outside are untouched (expected by construction
    /// of the test: nothing outside `out` may change).
    #[test]
    fn clean_removes_only_stale_files_inside_the_folder() {
        let tmp = tempfile::tempdir().unwrap();
        let out = tmp.path().join("out");
        let outside = tmp.path().join("outside");
        touch(&outside.join("keep.svg"));
        for f in ["README.md", "figures/new.svg", "figures/stale.svg", "families/old/gone.md", "peer-lcp.md"] {
            touch(&out.join(f));
        }
        touch(&out.join("old-top.csv"));
        touch(&out.join("notes.txt"));
        #[cfg(unix)]
        {
            std::os::unix::fs::symlink(&outside, out.join("figures/link")).unwrap();
            std::os::unix::fs::symlink(outside.join("keep.svg"), out.join("figures/file-link.svg")).unwrap();
        }
        let mut written = Manifest::default();
        written.add(&out, out.join("README.md"));
        written.add(&out, "figures/new.svg");
        let previous: BTreeSet<PathBuf> = [PathBuf::from("old-top.csv")].into();
        let done = clean(&out, &written, &previous).unwrap();
        assert!(out.join("README.md").exists() && out.join("figures/new.svg").exists());
        assert!(out.join("peer-lcp.md").exists(), "a declared input");
        assert!(!out.join("figures/stale.svg").exists());
        assert!(!out.join("families/old").exists(), "an emptied folder goes");
        assert!(!out.join("old-top.csv").exists(), "listed by the previous manifest");
        assert!(out.join("notes.txt").exists());
        assert_eq!(done.unknown, vec![PathBuf::from("notes.txt")]);
        assert!(outside.join("keep.svg").exists(), "nothing outside the folder is touched");
        #[cfg(unix)]
        {
            assert!(std::fs::symlink_metadata(out.join("figures/link")).is_err(), "the link itself is removed");
            assert!(std::fs::symlink_metadata(out.join("figures/file-link.svg")).is_err());
            assert!(outside.is_dir() && outside.join("keep.svg").exists());
        }
        assert!(done.removed.contains(&PathBuf::from("figures/stale.svg")));
    }
}
