//! The terrain made once per device and settings, and shared: the height
//! field, the chunks' boxes and the quadtree over them, and the maps on the
//! GPU, built in steps (heights, normals and boxes, upload) so that a
//! browser page can show its progress.

use std::sync::Arc;

use common::Gpu;
use common::preparation::{Preparation, Step};
use common::timing::measure;

use crate::chunks::{Aabb, chunk_bounds};
use crate::heightfield::{CHUNK_QUADS, HeightField, HeightRows, TerrainSettings};
use crate::quadtree::Quadtree;
use crate::terrain_maps::{TerrainMaps, normal_rows};

/// The terrain's CPU and GPU data for one set of settings: the height
/// field, each chunk's box and the quadtree over them, the maps on the
/// GPU, and how long the heights and the rest took to make (ms).
pub struct TerrainData {
    pub field: HeightField,
    /// Chunk (x, z)'s box at `z * chunks_per_side + x`.
    pub chunk_bounds: Vec<Aabb>,
    pub quadtree: Quadtree,
    pub maps: TerrainMaps,
    pub timings: (f64, f64),
}

impl TerrainData {
    /// The terrain of `field` with its boxes, quadtree and maps made on the
    /// device in one go (tests that build a field of their own use this).
    pub fn from_field(gpu: &Gpu, field: HeightField) -> Self {
        let n = field.settings.chunks_per_side;
        let chunk_bounds: Vec<Aabb> = (0..n * n).map(|i| chunk_bounds(&field, i % n, i / n)).collect();
        let normals = normal_rows(&field, 0..field.size);
        let maps = TerrainMaps::upload(&gpu.device, &gpu.queue, &field, &normals);
        Self { quadtree: Quadtree::new(&chunk_bounds, n), field, chunk_bounds, maps, timings: (0.0, 0.0) }
    }
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
                    unfinished => build = unfinished.step(gpu),
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
            match unfinished.step(gpu) {
                TerrainBuild::Done(data) => Step::Done(gpu.cached(settings, || data)),
                next => Step::Progress(build.insert(next).progress()),
            }
        })
    }
}

/// The terrain made a slice at a time: rows of heights, then rows of
/// normals and chunk boxes, then the upload. [`TerrainData::get`] takes the
/// same steps in one go, so every test of the terrain tests the steps too.
enum TerrainBuild {
    /// Milliseconds spent so far in `ms`.
    Heights {
        rows: HeightRows,
        ms: f64,
    },
    /// Milliseconds spent on heights, then on the rest, in `timings`.
    Maps {
        field: HeightField,
        normals: Vec<[i8; 2]>,
        bounds: Vec<Aabb>,
        timings: (f64, f64),
    },
    Done(TerrainData),
}

impl TerrainBuild {
    /// 55 to 85 ms of heights a step, measured in Chromium on the machine
    /// the book's figures come from; a step of normals and boxes is cheaper.
    const HEIGHT_ROWS_PER_STEP: usize = 64;
    const CHUNK_ROWS_PER_STEP: u32 = 4;
    /// The heights' share of the whole work, as measured natively.
    const HEIGHTS_SHARE: f32 = 0.8;

    fn new(settings: TerrainSettings) -> Self {
        Self::Heights { rows: HeightRows::new(settings), ms: 0.0 }
    }

    /// The next slice of work done.
    fn step(self, gpu: &Gpu) -> Self {
        match self {
            Self::Heights { mut rows, ms } => {
                let ((), took) = measure(|| rows.add(Self::HEIGHT_ROWS_PER_STEP));
                if rows.done() < rows.size {
                    return Self::Heights { rows, ms: ms + took };
                }
                let normals = Vec::with_capacity(rows.size * rows.size);
                Self::Maps { field: rows.finish(), normals, bounds: Vec::new(), timings: (ms + took, 0.0) }
            }
            Self::Maps { field, mut normals, mut bounds, mut timings } => {
                let n = field.settings.chunks_per_side;
                let first = bounds.len() as u32 / n;
                if first < n {
                    // Rows of chunks, and the rows of samples they start with
                    // (the last step takes the field's last row too).
                    let chunk_rows = first..(first + Self::CHUNK_ROWS_PER_STEP).min(n);
                    let end = if chunk_rows.end == n { field.size } else { chunk_rows.end * CHUNK_QUADS };
                    let ((), ms) = measure(|| {
                        normals.extend(normal_rows(&field, first * CHUNK_QUADS..end));
                        bounds.extend(
                            chunk_rows
                                .flat_map(|cz| (0..n).map(move |cx| (cx, cz)))
                                .map(|(cx, cz)| chunk_bounds(&field, cx, cz)),
                        );
                    });
                    timings.1 += ms;
                    return Self::Maps { field, normals, bounds, timings };
                }
                // Every row is done: the upload is the last step.
                let (data, ms) = measure(|| {
                    let maps = TerrainMaps::upload(&gpu.device, &gpu.queue, &field, &normals);
                    let quadtree = Quadtree::new(&bounds, n);
                    TerrainData { field, chunk_bounds: bounds, quadtree, maps, timings }
                });
                Self::Done(TerrainData { timings: (timings.0, timings.1 + ms), ..data })
            }
            done @ Self::Done(_) => done,
        }
    }

    /// The fraction of the whole work done.
    fn progress(&self) -> f32 {
        match self {
            Self::Heights { rows, .. } => Self::HEIGHTS_SHARE * rows.done() as f32 / rows.size as f32,
            Self::Maps { field, bounds, .. } => {
                let chunks = field.settings.chunks_per_side.pow(2) as f32;
                // The upload is still to come.
                Self::HEIGHTS_SHARE + (1.0 - Self::HEIGHTS_SHARE) * 0.95 * bounds.len() as f32 / chunks
            }
            Self::Done(_) => 1.0,
        }
    }
}
