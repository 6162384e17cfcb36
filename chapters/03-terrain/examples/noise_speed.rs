//! Nanoseconds per `perlin3` call on one thread:
//! `cargo run --release -p terrain --example noise_speed`.
fn main() {
    let n = 20_000_000;
    let start = std::time::Instant::now();
    let mut sum = 0.0;
    for i in 0..n {
        let x = i as f64 * 0.001;
        sum += terrain::noise::perlin3(x, x * 0.37 + 0.5, 7.81);
    }
    let ns = start.elapsed().as_secs_f64() * 1e9 / n as f64;
    println!("{ns:.1} ns per perlin3 call (checksum {sum:.3})");
}
