//! Times the terrain's CPU work at the default 4097² samples:
//! `cargo run --release -p terrain --example generation_time`.

use std::time::Instant;

use terrain::chunks::chunk_bounds;
use terrain::heightfield::{HeightField, TerrainSettings};
use terrain::terrain_maps::normal_rows;

fn main() {
    let settings = TerrainSettings::default();
    let start = Instant::now();
    let field = HeightField::generate(settings);
    let generated = start.elapsed();
    let start = Instant::now();
    let normals = normal_rows(&field, 0..field.size);
    let n = settings.chunks_per_side;
    let boxes: Vec<_> = (0..n * n).map(|i| chunk_bounds(&field, i % n, i / n)).collect();
    let rest = start.elapsed();
    println!(
        "{0}×{0} height samples in {1:.0} ms; {2} packed normals and {3} chunk boxes in {4:.0} ms",
        field.size,
        generated.as_secs_f64() * 1e3,
        normals.len(),
        boxes.len(),
        rest.as_secs_f64() * 1e3
    );
}
