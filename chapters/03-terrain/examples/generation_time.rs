//! Times the terrain's CPU work at the default 4097² samples:
//! `cargo run --release -p terrain --example generation_time`.

use std::time::Instant;

use terrain::chunks::{chunk_bounds, chunk_vertices};
use terrain::heightfield::{HeightField, TerrainSettings};

fn main() {
    let settings = TerrainSettings::default();
    let start = Instant::now();
    let field = HeightField::generate(settings);
    let generated = start.elapsed();
    let start = Instant::now();
    let n = settings.chunks_per_side;
    let mut vertices = 0;
    for cz in 0..n {
        for cx in 0..n {
            vertices += chunk_vertices(&field, cx, cz).len();
            let _ = chunk_bounds(&field, cx, cz);
        }
    }
    let meshed = start.elapsed();
    println!(
        "{0}×{0} height samples in {1:.0} ms; {vertices} chunk vertices and bounds in {2:.0} ms",
        field.size,
        generated.as_secs_f64() * 1e3,
        meshed.as_secs_f64() * 1e3
    );
}
