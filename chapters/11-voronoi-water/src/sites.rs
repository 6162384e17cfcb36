//! The Voronoi diagram's sites: points in the tile (0..1)² that wander,
//! each moving slowly in a direction that turns gradually. A site's path
//! is a pure function of time and its seed, so any scene time gives the
//! same diagram, however it was reached.

use common::glam::{DVec2, Vec2};

/// Sites in the chapter's diagram unless the slider says otherwise.
pub const DEFAULT_COUNT: u32 = 64;
/// The most sites the slider allows (the bench's largest count).
pub const MAX_COUNT: u32 = 16_384;
/// The seed of the chapter's sites.
pub const DEFAULT_SEED: u32 = 11;

/// Site positions in tile coordinates [0, 1)², at scene time `time`, for the
/// chapter's default site count and seed, in index order.
pub fn positions(time: f32) -> Vec<Vec2> {
    wandering(DEFAULT_COUNT, DEFAULT_SEED, time)
}

/// A fixed integer hash to [0, 1): the same on every machine.
fn hash(mut x: u32) -> f64 {
    x ^= x >> 16;
    x = x.wrapping_mul(0x7feb_352d);
    x ^= x >> 15;
    x = x.wrapping_mul(0x846c_a68b);
    x ^= x >> 16;
    f64::from(x >> 8) / f64::from(1u32 << 24)
}

// ANCHOR: wander
/// `count` sites of seed `seed` at `time`. Each site circles slowly around
/// a point that itself circles, more slowly, around where the site started:
/// the sum of two turning motions, so its heading turns gradually, at a
/// rate that drifts. About 0.5 m/s on the chapter's 32 m tile.
///
/// The phases are worked out in f64: at t = 10⁶ s an f32 angle would be
/// off by a sixteenth of a radian, and the sites would jitter.
pub fn wandering(count: u32, seed: u32, time: f32) -> Vec<Vec2> {
    let t = f64::from(time);
    let tau = std::f64::consts::TAU;
    (0..count)
        .map(|i| {
            let h = |k: u32| hash(seed.wrapping_mul(0x9e37_79b9) ^ i.wrapping_mul(8) ^ k.wrapping_mul(0x85eb_ca6b));
            let start = DVec2::new(h(0), h(1));
            let sign = if h(2) < 0.5 { -1.0 } else { 1.0 };
            // The slow circle: 0.05–0.12 rad/s, moving at 0.012 tiles/s.
            let slow_rate = sign * (0.05 + 0.07 * h(3));
            let slow = circle(0.012 / slow_rate.abs(), slow_rate * t + tau * h(4), tau * h(4));
            // The quick one, the other way round: 0.2–0.4 rad/s.
            let quick_rate = -sign * (0.2 + 0.2 * h(5));
            let quick = circle(0.004 / quick_rate.abs(), quick_rate * t + tau * h(6), tau * h(6));
            let p = start + slow + quick;
            Vec2::new(p.x.rem_euclid(1.0) as f32, p.y.rem_euclid(1.0) as f32).fract()
        })
        .collect()
}

/// Where a point on a circle of `radius` is at angle `angle`, relative to
/// where it was at angle `start`.
fn circle(radius: f64, angle: f64, start: f64) -> DVec2 {
    let angle = angle.rem_euclid(std::f64::consts::TAU);
    radius * (DVec2::new(angle.cos(), angle.sin()) - DVec2::new(start.cos(), start.sin()))
}
// ANCHOR_END: wander

// ANCHOR: torus
/// From `a` to `b` the short way round the tile, which wraps at its edges
/// (a torus): each coordinate of the answer is in −0.5..0.5.
pub fn torus_offset(a: Vec2, b: Vec2) -> Vec2 {
    let d = b - a;
    d - d.round()
}

/// The index of the site nearest `p` under the torus distance (the first,
/// for sites at exactly the same distance). What the diagram should show.
pub fn nearest(sites: &[Vec2], p: Vec2) -> Option<usize> {
    let distance = |s: &Vec2| torus_offset(p, *s).length_squared();
    (0..sites.len()).min_by(|&a, &b| distance(&sites[a]).total_cmp(&distance(&sites[b])))
}
// ANCHOR_END: torus

// ANCHOR: covering
/// An upper bound on how far any point of the tile is from its nearest
/// site: the radius every cone must reach for the diagram to have no holes.
///
/// The tile is cut into a grid of squares; for each square's centre the
/// nearest site is found by searching rings of squares outwards, and no
/// point of that square can be farther from a site than that distance plus
/// half the square's diagonal. About O(n) for n sites.
pub fn covering_radius(sites: &[Vec2]) -> f32 {
    if sites.is_empty() {
        return 0.0;
    }
    let g = ((2.0 * (sites.len() as f32).sqrt()).ceil() as usize).clamp(8, 256);
    let cell_of = |v: f32| ((v.rem_euclid(1.0) * g as f32) as usize).min(g - 1);
    let mut buckets = vec![Vec::new(); g * g];
    for s in sites {
        buckets[cell_of(s.y) * g + cell_of(s.x)].push(*s);
    }
    let mut worst = 0.0f32;
    for cy in 0..g {
        for cx in 0..g {
            let centre = Vec2::new((cx as f32 + 0.5) / g as f32, (cy as f32 + 0.5) / g as f32);
            let mut best = f32::MAX;
            for ring in 0..=g / 2 + 1 {
                for (dx, dy) in ring_cells(ring as i64) {
                    let x = (cx as i64 + dx).rem_euclid(g as i64) as usize;
                    let y = (cy as i64 + dy).rem_euclid(g as i64) as usize;
                    for s in &buckets[y * g + x] {
                        best = best.min(torus_offset(centre, *s).length());
                    }
                }
                // Every square in the next ring is at least this far away.
                if best <= (ring as f32 + 0.5) / g as f32 {
                    break;
                }
            }
            worst = worst.max(best);
        }
    }
    worst + std::f32::consts::FRAC_1_SQRT_2 / g as f32
}
// ANCHOR_END: covering

/// The squares at Chebyshev distance `ring` from (0, 0), as offsets.
fn ring_cells(ring: i64) -> impl Iterator<Item = (i64, i64)> {
    (-ring..=ring)
        .flat_map(move |dy| (-ring..=ring).map(move |dx| (dx, dy)))
        .filter(move |(dx, dy)| dx.abs().max(dy.abs()) == ring)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sites_stay_in_the_tile_and_move_slowly() {
        let before = positions(100.0);
        let after = positions(101.0);
        assert_eq!(before.len(), DEFAULT_COUNT as usize);
        for (a, b) in before.iter().zip(&after) {
            assert!(a.cmpge(Vec2::ZERO).all() && a.cmplt(Vec2::ONE).all(), "{a} is outside [0, 1)²");
            let step = torus_offset(*a, *b).length();
            assert!(step < 0.03, "a site moved {step} tiles in a second");
        }
    }

    #[test]
    fn a_sites_heading_turns_gradually() {
        // Headings a second apart differ by less than 30° for every site.
        let at = |t: f32| wandering(16, 3, t);
        for t in [0.0, 50.0, 5000.0] {
            let (a, b, c) = (at(t), at(t + 1.0), at(t + 2.0));
            for i in 0..16 {
                let first = torus_offset(a[i], b[i]);
                let second = torus_offset(b[i], c[i]);
                assert!(first.angle_to(second).abs().to_degrees() < 30.0, "site {i} at {t} s turned too fast");
            }
        }
    }

    #[test]
    fn sites_are_a_pure_function_of_time_even_after_a_million_seconds() {
        // What was asked before, and on which thread, changes nothing: a
        // cache or an integrator carried from call to call would.
        let first = positions(1e6);
        for t in [3.0, 1e6 - 1.0, 0.0, 2e6] {
            positions(t);
        }
        assert_eq!(positions(1e6), first, "after other times");
        assert_eq!(std::thread::spawn(|| positions(1e6)).join().unwrap(), first, "on another thread");
        // At 0 s both circles are at their starting angles: every site is
        // where its seed put it, (h(0), h(1)) of the hash.
        for (i, p) in positions(0.0).iter().enumerate() {
            let h =
                |k: u32| hash(DEFAULT_SEED.wrapping_mul(0x9e37_79b9) ^ (i as u32 * 8) ^ k.wrapping_mul(0x85eb_ca6b));
            assert!(p.distance(Vec2::new(h(0) as f32, h(1) as f32)) < 1e-6, "site {i} at 0 s: {p}");
        }
        // Still moving smoothly: 1/16 s (f32's step at 10⁶) moves a site a
        // tiny distance, not a jump.
        let (a, b) = (positions(1e6), positions(1e6 + 0.0625));
        for (p, q) in a.iter().zip(&b) {
            assert!(torus_offset(*p, *q).length() < 0.002);
        }
    }

    #[test]
    fn nearest_wraps_around_the_tile() {
        let sites = [Vec2::new(0.05, 0.5), Vec2::new(0.7, 0.5)];
        // 0.95 is 0.1 from the first site across the edge, 0.25 from the second.
        assert_eq!(nearest(&sites, Vec2::new(0.95, 0.5)), Some(0));
        assert_eq!(nearest(&sites, Vec2::new(0.6, 0.5)), Some(1));
    }

    /// The bound is never below the true covering radius, measured by brute
    /// force on a fine grid, and not wildly above it.
    #[test]
    fn covering_radius_bounds_every_point() {
        for count in [1, 2, 7, 64, 300] {
            let sites = wandering(count, 5, 12.0);
            let bound = covering_radius(&sites);
            let mut worst = 0.0f32;
            for y in 0..128 {
                for x in 0..128 {
                    let p = Vec2::new((x as f32 + 0.5) / 128.0, (y as f32 + 0.5) / 128.0);
                    let i = nearest(&sites, p).unwrap();
                    worst = worst.max(torus_offset(p, sites[i]).length());
                }
            }
            assert!(bound >= worst, "{count} sites: bound {bound} below the measured {worst}");
            assert!(bound < worst * 1.6 + 0.05, "{count} sites: bound {bound} far above {worst}");
        }
        // Two sites at the same place, or one site: still a radius.
        assert!(covering_radius(&[Vec2::splat(0.3), Vec2::splat(0.3)]) >= std::f32::consts::FRAC_1_SQRT_2);
    }
}
