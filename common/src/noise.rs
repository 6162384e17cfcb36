//! Ken Perlin's improved noise (2002) and its fractal sum, fBm.
//!
//! Every function is `#[inline]`: the caller's crate compiles it, so chapter
//! 03's terrain, optimised even in debug builds, generates its 16.8 million
//! samples at full speed although `common` is not optimised.
//!
//! Written out here rather than taken from a crate because it is what this
//! chapter teaches: a lattice of pseudo-random gradients, blended smoothly.

// ANCHOR: permutation
/// Perlin's reference permutation of 0..=255, repeated once so that
/// `P[i + 1]` never needs wrapping. Changing it changes every terrain.
const P: [u8; 512] = {
    const BASE: [u8; 256] = [
        151, 160, 137, 91, 90, 15, 131, 13, 201, 95, 96, 53, 194, 233, 7, 225, 140, 36, 103, 30, 69, 142, 8, 99, 37,
        240, 21, 10, 23, 190, 6, 148, 247, 120, 234, 75, 0, 26, 197, 62, 94, 252, 219, 203, 117, 35, 11, 32, 57, 177,
        33, 88, 237, 149, 56, 87, 174, 20, 125, 136, 171, 168, 68, 175, 74, 165, 71, 134, 139, 48, 27, 166, 77, 146,
        158, 231, 83, 111, 229, 122, 60, 211, 133, 230, 220, 105, 92, 41, 55, 46, 245, 40, 244, 102, 143, 54, 65, 25,
        63, 161, 1, 216, 80, 73, 209, 76, 132, 187, 208, 89, 18, 169, 200, 196, 135, 130, 116, 188, 159, 86, 164, 100,
        109, 198, 173, 186, 3, 64, 52, 217, 226, 250, 124, 123, 5, 202, 38, 147, 118, 126, 255, 82, 85, 212, 207, 206,
        59, 227, 47, 16, 58, 17, 182, 189, 28, 42, 223, 183, 170, 213, 119, 248, 152, 2, 44, 154, 163, 70, 221, 153,
        101, 155, 167, 43, 172, 9, 129, 22, 39, 253, 19, 98, 108, 110, 79, 113, 224, 232, 178, 185, 112, 104, 218, 246,
        97, 228, 251, 34, 242, 193, 238, 210, 144, 12, 191, 179, 162, 241, 81, 51, 145, 235, 249, 14, 239, 107, 49,
        192, 214, 31, 181, 199, 106, 157, 184, 84, 204, 176, 115, 121, 50, 45, 127, 4, 150, 254, 138, 236, 205, 93,
        222, 114, 67, 29, 24, 72, 243, 141, 128, 195, 78, 66, 215, 61, 156, 180,
    ];
    let mut table = [0; 512];
    let mut i = 0;
    while i < 512 {
        table[i] = BASE[i % 256];
        i += 1;
    }
    table
};
// ANCHOR_END: permutation

// ANCHOR: perlin3
/// 6t⁵ − 15t⁴ + 10t³: eases 0 → 1 with zero first and second derivatives at
/// both ends, so neighbouring lattice cells join without creases.
#[inline]
fn fade(t: f64) -> f64 {
    t * t * t * (t * (t * 6.0 - 15.0) + 10.0)
}

#[inline]
fn lerp(t: f64, a: f64, b: f64) -> f64 {
    a + t * (b - a)
}

/// Perlin's twelve cube-edge directions, four repeated to make sixteen,
/// indexed by the low four bits of a hash. The reference code picks them
/// with `if`s on the hash bits (h < 8 ? x : y, and so on); a table gives the
/// same sums without branches the CPU cannot predict (the hash is random).
const GRADIENTS: [[f64; 3]; 16] = [
    [1.0, 1.0, 0.0],
    [-1.0, 1.0, 0.0],
    [1.0, -1.0, 0.0],
    [-1.0, -1.0, 0.0],
    [1.0, 0.0, 1.0],
    [-1.0, 0.0, 1.0],
    [1.0, 0.0, -1.0],
    [-1.0, 0.0, -1.0],
    [0.0, 1.0, 1.0],
    [0.0, -1.0, 1.0],
    [0.0, 1.0, -1.0],
    [0.0, -1.0, -1.0],
    [1.0, 1.0, 0.0],
    [0.0, -1.0, 1.0],
    [-1.0, 1.0, 0.0],
    [0.0, -1.0, -1.0],
];

/// Dot product of (x, y, z) with the gradient chosen by `hash`.
#[inline]
fn grad(hash: u8, x: f64, y: f64, z: f64) -> f64 {
    let g = GRADIENTS[usize::from(hash & 15)];
    g[0] * x + g[1] * y + g[2] * z
}

/// `x.floor()`, without the libm call it compiles to on baseline x86-64
/// (no SSE4.1): truncate, then step down for negative non-integers.
#[inline]
fn floor(x: f64) -> f64 {
    let t = x as i64 as f64;
    if t > x { t - 1.0 } else { t }
}

/// Improved Perlin noise at (x, y, z), in about -1..1, exactly 0 at
/// integer points. Reproduces Perlin's reference implementation.
#[inline]
pub fn perlin3(x: f64, y: f64, z: f64) -> f64 {
    // The unit cube that contains the point, wrapped to the 256-cell table…
    let (fx, fy, fz) = (floor(x), floor(y), floor(z));
    let (xi, yi, zi) = ((fx as i64 & 255) as usize, (fy as i64 & 255) as usize, (fz as i64 & 255) as usize);
    // …and where the point lies inside it.
    let (x, y, z) = (x - fx, y - fy, z - fz);
    let (u, v, w) = (fade(x), fade(y), fade(z));

    // Hash the eight corners to pick their gradients. (`& 511` changes no
    // index, all are below 512, but lets the compiler drop bounds checks.)
    let p = |i: usize| P[i & 511] as usize;
    let a = p(xi) + yi;
    let (aa, ab) = (p(a) + zi, p(a + 1) + zi);
    let b = p(xi + 1) + yi;
    let (ba, bb) = (p(b) + zi, p(b + 1) + zi);

    // Blend the eight corner contributions, x first, then y, then z.
    lerp(
        w,
        lerp(
            v,
            lerp(u, grad(P[aa & 511], x, y, z), grad(P[ba & 511], x - 1.0, y, z)),
            lerp(u, grad(P[ab & 511], x, y - 1.0, z), grad(P[bb & 511], x - 1.0, y - 1.0, z)),
        ),
        lerp(
            v,
            lerp(u, grad(P[(aa + 1) & 511], x, y, z - 1.0), grad(P[(ba + 1) & 511], x - 1.0, y, z - 1.0)),
            lerp(u, grad(P[(ab + 1) & 511], x, y - 1.0, z - 1.0), grad(P[(bb + 1) & 511], x - 1.0, y - 1.0, z - 1.0)),
        ),
    )
}
// ANCHOR_END: perlin3

// ANCHOR: fbm
/// Fractional Brownian motion (fBm): several octaves of noise, each at `lacunarity`
/// times the frequency and `persistence` times the amplitude of the last.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Fbm {
    pub octaves: u32,
    pub persistence: f64,
    pub lacunarity: f64,
}

impl Fbm {
    /// The sum at (x, y) on the slice `z` of 3D noise (a seed picks the
    /// slice), divided by the sum of amplitudes so it stays in about -1..1
    /// whatever the octave count.
    #[inline]
    pub fn sample(&self, x: f64, y: f64, z: f64) -> f64 {
        let (mut sum, mut total, mut amplitude, mut frequency) = (0.0, 0.0, 1.0, 1.0);
        for _ in 0..self.octaves {
            sum += amplitude * perlin3(x * frequency, y * frequency, z);
            total += amplitude;
            amplitude *= self.persistence;
            frequency *= self.lacunarity;
        }
        if total > 0.0 { sum / total } else { 0.0 }
    }
}
// ANCHOR_END: fbm

#[cfg(test)]
mod tests {
    use super::*;

    /// Values of Perlin's published Java reference (`ImprovedNoise.noise`),
    /// computed with an independent transcription of it, not with this code.
    /// The first is the one the issue quotes (3.14 is a coordinate, not π).
    #[allow(clippy::approx_constant)]
    const REFERENCE: [((f64, f64, f64), f64); 8] = [
        ((3.14, 42.0, 7.0), 0.13691995878400012),
        ((0.5, 0.5, 0.5), -0.25),
        ((1.25, 2.75, -3.5), -0.07993936538696289),
        ((-7.3, 0.1, 123.456), -0.23083470156530034),
        ((10.0, 20.0, 30.0), 0.0),
        ((0.1, 0.2, 0.3), 0.35122924878110723),
        ((255.9, -1.5, 64.25), 0.5218654726562537),
        ((1000.7, 3.3, 0.0), -0.056284767840036574),
    ];

    #[test]
    fn matches_the_reference_implementation() {
        for ((x, y, z), expected) in REFERENCE {
            let got = perlin3(x, y, z);
            assert!((got - expected).abs() < 1e-12, "perlin3({x}, {y}, {z}) = {got}, reference {expected}");
        }
    }

    /// The table against the reference's branches, for every hash.
    #[test]
    fn gradient_table_matches_the_reference_branches() {
        let reference = |h: u8, x: f64, y: f64, z: f64| {
            let u = if h < 8 { x } else { y };
            let v = if h < 4 {
                y
            } else if h == 12 || h == 14 {
                x
            } else {
                z
            };
            (if h & 1 == 0 { u } else { -u }) + (if h & 2 == 0 { v } else { -v })
        };
        for h in 0..16 {
            assert_eq!(grad(h, 0.3, -1.7, 2.9), reference(h, 0.3, -1.7, 2.9), "hash {h}");
        }
    }

    #[test]
    fn repeats_every_256_units() {
        assert!((perlin3(3.7, 1.2, 0.4) - perlin3(259.7, 1.2, 0.4)).abs() < 1e-12);
    }

    #[test]
    fn stays_in_range_and_is_continuous() {
        let mut previous = perlin3(0.0, 0.5, 0.25);
        for i in 1..10_000 {
            let x = i as f64 * 0.001;
            let value = perlin3(x, 0.5, 0.25);
            assert!(value.abs() <= 1.0);
            assert!((value - previous).abs() < 0.01, "jump at x = {x}");
            previous = value;
        }
    }

    #[test]
    fn fbm_sums_octaves_at_rising_frequency_and_falling_amplitude() {
        let one = Fbm { octaves: 1, persistence: 0.5, lacunarity: 2.0 };
        assert_eq!(one.sample(1.3, 2.7, 0.5), perlin3(1.3, 2.7, 0.5));
        // Three octaves: amplitudes 1, 0.4, 0.16 at frequencies 1, 3, 9, over their sum 1.56.
        let three = Fbm { octaves: 3, persistence: 0.4, lacunarity: 3.0 };
        let (x, y, z) = (1.3, 2.7, 0.5);
        let expected =
            (perlin3(x, y, z) + 0.4 * perlin3(3.0 * x, 3.0 * y, z) + 0.16 * perlin3(9.0 * x, 9.0 * y, z)) / 1.56;
        assert!((three.sample(x, y, z) - expected).abs() < 1e-12);
        assert_eq!(Fbm { octaves: 0, ..one }.sample(1.0, 2.0, 3.0), 0.0);
    }
}
