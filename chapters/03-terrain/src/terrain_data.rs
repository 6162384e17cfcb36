//! The terrain made once per device and settings, and shared: the height
//! field and the chunk meshes, built in steps (heights, meshes, upload) so
//! that a browser page can show its progress.

use std::sync::Arc;

use common::preparation::{Preparation, Step};
use common::timing::measure;
use common::{Gpu, wgpu};

use crate::chunks::{Aabb, CHUNK_VERTICES, TerrainVertex};
use crate::heightfield::{HeightField, HeightRows, TerrainSettings};
use crate::terrain_mesh::TerrainMesh;

/// The terrain's CPU and GPU data for one set of settings: the height
/// field, the chunk meshes, and how long each took to make (ms).
pub struct TerrainData {
    pub field: HeightField,
    pub mesh: TerrainMesh,
    pub timings: (f64, f64),
}

impl TerrainData {
    /// The data for `settings`, made once per device: later chapters, and
    /// tests that create chapters again and again, share it.
    pub fn get(gpu: &Gpu, settings: TerrainSettings) -> Arc<Self> {
        gpu.cached(settings, || {
            let mut build = TerrainBuild::new(settings);
            loop {
                match build {
                    TerrainBuild::Done(data) => return data,
                    unfinished => build = unfinished.step(&gpu.device),
                }
            }
        })
    }

    /// [`TerrainData::get`] in steps, for [`Chapter::prepare`]: a browser
    /// page shows its progress between them. Ready at once when the data
    /// is already made.
    ///
    /// [`Chapter::prepare`]: common::Chapter::prepare
    pub fn prepare(gpu: &Gpu, settings: TerrainSettings) -> Preparation<Arc<Self>> {
        if gpu.is_cached::<TerrainSettings, Self>(&settings) {
            return Preparation::ready(Self::get(gpu, settings));
        }
        let mut build = Some(TerrainBuild::new(settings));
        Preparation::in_steps("generating the terrain", move |gpu| {
            let unfinished = build.take().expect("no step after the last");
            match unfinished.step(&gpu.device) {
                TerrainBuild::Done(data) => Step::Done(gpu.cached(settings, || data)),
                next => Step::Progress(build.insert(next).progress()),
            }
        })
    }
}

/// The terrain made a slice at a time: rows of heights, then rows of
/// chunk meshes, then the upload. [`TerrainData::get`] takes the same
/// steps in one go, so every test of the terrain tests the steps too.
enum TerrainBuild {
    /// Milliseconds spent so far in `ms`.
    Heights {
        rows: HeightRows,
        ms: f64,
    },
    /// Milliseconds spent on heights, then on meshes, in `timings`.
    Meshes {
        field: HeightField,
        vertices: Vec<TerrainVertex>,
        bounds: Vec<Aabb>,
        timings: (f64, f64),
    },
    Done(TerrainData),
}

impl TerrainBuild {
    /// 55 to 85 ms of heights and about 60 ms of meshes a step, measured
    /// in Chromium on the machine the book's figures come from.
    const HEIGHT_ROWS_PER_STEP: usize = 64;
    const CHUNK_ROWS_PER_STEP: u32 = 4;
    /// The heights' share of the whole work, as measured natively (1650 ms
    /// of heights to 645 ms of meshes).
    const HEIGHTS_SHARE: f32 = 0.72;

    fn new(settings: TerrainSettings) -> Self {
        Self::Heights { rows: HeightRows::new(settings), ms: 0.0 }
    }

    /// The next slice of work done.
    fn step(self, device: &wgpu::Device) -> Self {
        match self {
            Self::Heights { mut rows, ms } => {
                let ((), took) = measure(|| rows.add(Self::HEIGHT_ROWS_PER_STEP));
                if rows.done() < rows.size {
                    return Self::Heights { rows, ms: ms + took };
                }
                let chunks = rows.settings.chunks_per_side.pow(2) as usize;
                let vertices = Vec::with_capacity(chunks * CHUNK_VERTICES as usize);
                Self::Meshes { field: rows.finish(), vertices, bounds: Vec::new(), timings: (ms + took, 0.0) }
            }
            Self::Meshes { field, mut vertices, mut bounds, mut timings } => {
                let n = field.settings.chunks_per_side;
                let first = bounds.len() as u32 / n;
                if first < n {
                    let rows = first..(first + Self::CHUNK_ROWS_PER_STEP).min(n);
                    let ((more_vertices, more_bounds), ms) = measure(|| TerrainMesh::chunk_rows(&field, rows));
                    vertices.extend(more_vertices);
                    bounds.extend(more_bounds);
                    timings.1 += ms;
                    return Self::Meshes { field, vertices, bounds, timings };
                }
                // Every chunk is built: the upload is the last step.
                let (mesh, ms) = measure(|| TerrainMesh::upload(device, n, &vertices, bounds));
                timings.1 += ms;
                Self::Done(TerrainData { field, mesh, timings })
            }
            done @ Self::Done(_) => done,
        }
    }

    /// The fraction of the whole work done.
    fn progress(&self) -> f32 {
        match self {
            Self::Heights { rows, .. } => Self::HEIGHTS_SHARE * rows.done() as f32 / rows.size as f32,
            Self::Meshes { field, bounds, .. } => {
                let chunks = field.settings.chunks_per_side.pow(2) as f32;
                // The upload is still to come.
                Self::HEIGHTS_SHARE + (1.0 - Self::HEIGHTS_SHARE) * 0.95 * bounds.len() as f32 / chunks
            }
            Self::Done(_) => 1.0,
        }
    }
}
