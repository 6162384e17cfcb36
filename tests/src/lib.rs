//! The snapshot registry: every chapter, every view, rendered offscreen at a
//! fixed size and time and compared with `tests/snapshots/<chapter>/<view>.png`.
//!
//! `cargo test` checks them; only `cargo xtask snapshot --bless` (which runs
//! this crate's binary with `--bless`) writes references.

use std::path::{Path, PathBuf};

use common::headless::{self, RenderRequest};
use common::snapshot::{self, Comparison, SnapshotError, Tolerance};
use common::{Chapter, Gpu, GpuNeeds, View, anyhow, image};

/// Snapshots are rendered at this size: large enough to judge, small enough
/// for a software rasteriser to render and compare quickly.
pub const WIDTH: u32 = 800;
pub const HEIGHT: u32 = 450;

/// One chapter as the snapshot tests see it.
pub struct Entry {
    pub name: &'static str,
    pub views: &'static [View],
    pub time: f32,
    needs: GpuNeeds,
    tolerance: fn(usize) -> Tolerance,
    render: fn(&Gpu, &RenderRequest) -> anyhow::Result<image::RgbaImage>,
}

fn entry<C: Chapter>() -> Entry {
    Entry {
        name: C::NAME,
        views: C::VIEWS,
        time: C::SNAPSHOT_TIME,
        needs: C::gpu_needs(),
        tolerance: C::snapshot_tolerance,
        render: headless::render_image::<C>,
    }
}

/// Every chapter, in book order. A new chapter adds one line here.
pub fn chapters() -> Vec<Entry> {
    vec![
        entry::<triangle::Triangle>(),
        entry::<camera::CameraChapter>(),
        entry::<terrain::TerrainChapter>(),
        entry::<fog::FogChapter>(),
        entry::<instancing::InstancingChapter>(),
        entry::<skybox::SkyboxChapter>(),
        entry::<water::WaterChapter>(),
    ]
}

pub fn find(name: &str) -> Option<Entry> {
    chapters().into_iter().find(|e| e.name == name)
}

/// `tests/snapshots`, where the references live.
pub fn snapshot_dir() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("snapshots")
}

pub fn reference_path(chapter: &str, view: &str) -> PathBuf {
    snapshot_dir().join(chapter).join(format!("{view}.png"))
}

/// The outcome for one view.
pub struct ViewResult {
    pub view: &'static str,
    pub outcome: Result<Comparison, String>,
}

impl Entry {
    fn gpu(&self) -> anyhow::Result<Gpu> {
        Ok(Gpu::headless(self.needs)?)
    }

    fn render(&self, gpu: &Gpu, view: usize) -> anyhow::Result<image::RgbaImage> {
        (self.render)(gpu, &RenderRequest { width: WIDTH, height: HEIGHT, time: self.time, view })
    }

    /// Renders one view at the snapshot size and time, on a fresh device.
    pub fn render_view(&self, view: usize) -> anyhow::Result<image::RgbaImage> {
        self.render(&self.gpu()?, view)
    }

    /// Renders every view and compares each with its reference.
    pub fn check(&self) -> anyhow::Result<Vec<ViewResult>> {
        let gpu = self.gpu()?;
        let mut results = Vec::new();
        for (i, view) in self.views.iter().enumerate() {
            let outcome = self.render(&gpu, i).map_err(|e| format!("{e:#}")).and_then(|image| {
                snapshot::check(&image, &reference_path(self.name, view.name), (self.tolerance)(i))
                    .map_err(|e: SnapshotError| e.to_string())
            });
            results.push(ViewResult { view: view.name, outcome });
        }
        Ok(results)
    }

    /// Renders every view and writes it as the new reference. Returns the paths.
    pub fn bless(&self) -> anyhow::Result<Vec<PathBuf>> {
        let gpu = self.gpu()?;
        let mut written = Vec::new();
        for (i, view) in self.views.iter().enumerate() {
            let path = reference_path(self.name, view.name);
            std::fs::create_dir_all(path.parent().expect("reference paths have a folder"))?;
            self.render(&gpu, i)?.save(&path)?;
            for stale in ["actual", "diff"] {
                let _ = std::fs::remove_file(snapshot::sibling(&path, stale));
            }
            written.push(path);
        }
        Ok(written)
    }
}

/// For `#[test]`s: checks one chapter and panics with every failing view.
pub fn assert_chapter(name: &str) {
    let entry = find(name).unwrap_or_else(|| panic!("{name} is not in snapshots::chapters()"));
    let results = entry.check().unwrap_or_else(|e| panic!("{name}: {e:#}"));
    let failures: Vec<String> =
        results.iter().filter_map(|r| r.outcome.as_ref().err().map(|e| format!("  {name}/{}: {e}", r.view))).collect();
    for r in &results {
        if let Ok(c) = &r.outcome {
            eprintln!("{name}/{}: {c}", r.view);
        }
    }
    assert!(failures.is_empty(), "snapshot failures:\n{}", failures.join("\n"));
}
