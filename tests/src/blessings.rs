//! The bless log, `tests/snapshots/BLESSINGS.md`: every reference picture
//! as it was blessed, with what it replaced, how far it moved, on which
//! adapter it was made and why. `cargo xtask snapshot --bless` appends to
//! it; the snapshot test fails on a reference whose bytes no entry names
//! (a picture changed by hand, or by a bless that was not recorded), and
//! compares a picture exactly on the adapter its reference was made on.

use std::fmt;
use std::path::{Path, PathBuf};

use common::{Gpu, anyhow};
use sha2::{Digest as _, Sha256};

/// The log's file name, beside the chapters' folders of references.
pub const FILE: &str = "BLESSINGS.md";

/// What the log says above its table, written when it is first made.
pub const HEADING: &str = "\
# The bless log

Every reference picture under `tests/snapshots/`, as it was blessed,
oldest first: its view, the first 16 hex digits of the SHA-256 of the
file it replaced (`old`, `-` for a new view) and of the file written
(`new`; `sha256sum` gives the same digits), the FLIP mean and the worst
16×16 patch of the new picture against the old one (rounding of one
colour level aside), the adapter that drew it, and why.

Only `cargo xtask snapshot --bless CHAPTER[/VIEW]... --reason \"...\"`
writes here (CONTRIBUTING.md, \"Blessing a picture\"). The snapshot test
fails on a reference whose bytes no entry names, and on the adapter an
entry names it requires the picture to match its reference within one
colour level per channel; other adapters are held to FLIP's tolerance.

| view | old | new | FLIP mean | worst patch | adapter | reason |
|---|---|---|---:|---:|---|---|
";

/// What an entry says of an adapter it does not know: the references
/// found when the log began that this machine's lavapipe does not draw
/// within one colour level (they were made on another machine).
pub const UNKNOWN_ADAPTER: &str = "unknown";

/// One line of the log.
#[derive(Clone, Debug, PartialEq)]
pub struct Entry {
    /// `chapter/view`.
    pub view: String,
    /// The hash of the reference replaced, `None` for a new view.
    pub old: Option<String>,
    pub new: String,
    /// FLIP mean and worst patch against the old picture; `None` where
    /// there was none to compare with.
    pub mean: Option<f32>,
    pub patch: Option<f32>,
    pub adapter: String,
    pub reason: String,
}

impl fmt::Display for Entry {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let or_dash = |value: Option<String>| value.unwrap_or_else(|| "-".into());
        write!(
            f,
            "| {} | {} | {} | {} | {} | {} | {} |",
            self.view,
            or_dash(self.old.clone()),
            self.new,
            or_dash(self.mean.map(|m| format!("{m:.5}"))),
            or_dash(self.patch.map(|p| format!("{p:.3}"))),
            escape(&self.adapter),
            escape(&self.reason)
        )
    }
}

/// The log as read from its file.
#[derive(Clone, Debug, Default)]
pub struct Log {
    pub entries: Vec<Entry>,
}

/// The log's path.
pub fn path() -> PathBuf {
    crate::snapshot_dir().join(FILE)
}

/// The first 16 hex digits of the SHA-256 of `bytes`: what the log calls
/// a picture by.
pub fn hash(bytes: &[u8]) -> String {
    Sha256::digest(bytes).iter().take(8).map(|b| format!("{b:02x}")).collect()
}

/// [`hash`] of a file's bytes.
pub fn hash_file(path: &Path) -> std::io::Result<String> {
    Ok(hash(&std::fs::read(path)?))
}

impl Log {
    /// Reads the log; a missing file is an empty log, a line that does not
    /// read is an error naming it.
    pub fn read() -> anyhow::Result<Self> {
        match std::fs::read_to_string(path()) {
            Ok(text) => Self::parse(&text).map_err(|e| anyhow::anyhow!("{}: {e}", path().display())),
            Err(e) if e.kind() == std::io::ErrorKind::NotFound => Ok(Self::default()),
            Err(e) => Err(anyhow::anyhow!("cannot read {}: {e}", path().display())),
        }
    }

    /// The entries of the log's table (the rows after its header).
    pub fn parse(text: &str) -> Result<Self, String> {
        let mut entries = Vec::new();
        let mut in_table = false;
        for (number, line) in text.lines().enumerate() {
            if line.starts_with("|---") {
                in_table = true;
                continue;
            }
            if !in_table || !line.starts_with('|') {
                continue;
            }
            let cells = split_row(line);
            let [view, old, new, mean, patch, adapter, reason] = cells.as_slice() else {
                return Err(format!("line {}: {} cells where an entry has 7: {line}", number + 1, cells.len()));
            };
            let optional = |cell: &String| (cell != "-").then(|| cell.clone());
            let number_in = |cell: &String| -> Result<Option<f32>, String> {
                optional(cell)
                    .map(|c| c.parse().map_err(|_| format!("line {}: `{c}` is no number", number + 1)))
                    .transpose()
            };
            entries.push(Entry {
                view: view.clone(),
                old: optional(old),
                new: new.clone(),
                mean: number_in(mean)?,
                patch: number_in(patch)?,
                adapter: adapter.clone(),
                reason: reason.clone(),
            });
        }
        Ok(Self { entries })
    }

    /// The last entry that wrote a file with `hash`: the blessing a
    /// reference with those bytes came from.
    /// The latest entry that blessed these bytes as `view`'s picture
    /// (`chapter/view`): a picture blessed for another view (a copy of
    /// `flat.png` over `default.png`) is no blessing of this one.
    pub fn blessing_of(&self, view: &str, hash: &str) -> Option<&Entry> {
        self.entries.iter().rev().find(|e| e.view == view && e.new == hash)
    }

    /// The adapter the reference at `reference` was made on, by the log;
    /// `None` when no entry names its bytes (or it cannot be read).
    pub fn adapter_of(&self, view: &str, reference: &Path) -> Option<&str> {
        let hash = hash_file(reference).ok()?;
        self.blessing_of(view, &hash).map(|e| e.adapter.as_str())
    }

    /// Appends `entries` to the log's file, making it (with its heading)
    /// when there is none.
    pub fn append(entries: &[Entry]) -> anyhow::Result<()> {
        use std::io::Write as _;
        if entries.is_empty() {
            return Ok(());
        }
        let path = path();
        let mut text = String::new();
        if !path.exists() {
            text.push_str(HEADING);
        }
        for entry in entries {
            text.push_str(&format!("{entry}\n"));
        }
        let mut file = std::fs::OpenOptions::new()
            .create(true)
            .append(true)
            .open(&path)
            .map_err(|e| anyhow::anyhow!("cannot write {}: {e}", path.display()))?;
        file.write_all(text.as_bytes())?;
        Ok(())
    }
}

/// Every reference under [`crate::snapshot_dir`] whose bytes no entry of
/// `log` names, one line each, saying what to do.
pub fn unlogged_references(log: &Log) -> anyhow::Result<Vec<String>> {
    let mut problems = Vec::new();
    for record in crate::chapters() {
        for view in record.views.iter().filter(|v| v.snapshot) {
            let reference = crate::reference_path(record.name, view.name);
            let Ok(hash) = hash_file(&reference) else { continue }; // a missing reference fails its view
            if log.blessing_of(&format!("{}/{}", record.name, view.name), &hash).is_none() {
                let (chapter, view) = (record.name, view.name);
                problems.push(format!(
                    "tests/snapshots/{chapter}/{view}.png (sha256 {hash}…) matches no entry of its view in tests/snapshots/{FILE}: \
                     a reference changes only through `cargo xtask snapshot --bless {chapter}/{view} --reason \"...\"`"
                ));
            }
        }
    }
    Ok(problems)
}

/// The adapter a picture was drawn on, as the log writes it: the GPU's
/// name, the backend and the driver; for a software rasteriser also the
/// CPU it ran on, not only its vector width: with every reference held
/// exact (2026-11-29), 32 of the 206 views blessed on an Intel Xeon with
/// AVX-512 differed by more than one level on this AMD EPYC, also
/// AVX-512, by up to 70 levels where FXAA and Sobel edges amplify a
/// rounding (voronoi-water's `edges`, lighting's `fxaa`). So exactness is
/// kept to the machine a reference was made on, and every other machine,
/// CI's included, holds it to FLIP.
pub fn adapter(gpu: &Gpu) -> String {
    let info = gpu.adapter.get_info();
    // lavapipe's driver is named in its adapter's name already.
    let driver =
        if info.name.starts_with(&info.driver) { info.driver_info } else { info.driver + " " + &info.driver_info };
    let mut line = format!("{} · {:?} · {driver}", info.name, info.backend);
    if info.device_type == common::wgpu::DeviceType::Cpu {
        line.push_str(&format!(" · {}", cpu()));
    }
    line
}

/// "Intel(R) Xeon(R) Processor, AVX-512": the CPU's name and the widest
/// vector instructions it has, from `/proc/cpuinfo` (Linux).
fn cpu() -> String {
    let info = std::fs::read_to_string("/proc/cpuinfo").unwrap_or_default();
    let field = |name: &str| {
        info.lines()
            .find(|l| l.starts_with(name))
            .and_then(|l| l.split_once(':'))
            .map(|(_, value)| value.trim().to_string())
    };
    let name = field("model name").unwrap_or_else(|| "an unknown CPU".into());
    let flags = field("flags").unwrap_or_default();
    let has = |flag: &str| flags.split_whitespace().any(|f| f == flag);
    let vectors = if has("avx512f") {
        "AVX-512"
    } else if has("avx2") {
        "AVX2"
    } else if has("avx") {
        "AVX"
    } else {
        "no AVX"
    };
    format!("{name}, {vectors}")
}

/// A table cell's text: `|` would end the cell.
fn escape(text: &str) -> String {
    text.replace('|', "\\|").replace('\n', " ")
}

/// A table row's cells, trimmed, with `\|` read back as `|`.
fn split_row(line: &str) -> Vec<String> {
    let inner = line.trim().trim_start_matches('|');
    let inner = inner.strip_suffix('|').unwrap_or(inner);
    let mut cells = vec![String::new()];
    let mut chars = inner.chars().peekable();
    while let Some(c) = chars.next() {
        match c {
            '\\' if chars.peek() == Some(&'|') => {
                cells.last_mut().expect("one cell at least").push('|');
                chars.next();
            }
            '|' => cells.push(String::new()),
            c => cells.last_mut().expect("one cell at least").push(c),
        }
    }
    cells.into_iter().map(|c| c.trim().to_string()).collect()
}
