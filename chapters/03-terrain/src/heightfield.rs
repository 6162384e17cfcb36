//! A height map sampled from fBm noise, with a cliff, and normals taken
//! from the whole field so that chunk borders have no seams.

use common::glam::Vec3;

use crate::noise::Fbm;

/// Quads along one side of a chunk (so a chunk has 65 × 65 vertices).
pub const CHUNK_QUADS: u32 = 64;

/// Everything that decides the shape of the terrain. Same settings, same
/// terrain, on every machine.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TerrainSettings {
    /// Chunks along one side; the field has `chunks * 64 + 1` samples a side.
    pub chunks_per_side: u32,
    /// Metres between neighbouring samples.
    pub spacing: f32,
    /// Metres from the lowest valley to the highest hill is about twice this.
    pub height: f32,
    /// Size of the largest hills, in metres (the first octave's wavelength).
    pub feature_size: f32,
    pub fbm: Fbm,
    /// Picks the slice of 3D noise the terrain is cut from.
    pub seed: u32,
    /// Height of the cliff that runs across the world, metres.
    pub cliff_height: f32,
}

impl Default for TerrainSettings {
    fn default() -> Self {
        Self {
            chunks_per_side: 64,
            spacing: 1.0,
            height: 140.0,
            feature_size: 900.0,
            fbm: Fbm { octaves: 7, persistence: 0.5, lacunarity: 2.0 },
            seed: 7,
            cliff_height: 35.0,
        }
    }
}

impl TerrainSettings {
    /// Samples along one side.
    pub const fn samples(&self) -> u32 {
        self.chunks_per_side * CHUNK_QUADS + 1
    }

    /// Metres along one side of the world.
    pub fn extent(&self) -> f32 {
        (self.samples() - 1) as f32 * self.spacing
    }

    // ANCHOR: height
    /// The terrain's height at world position (x, z): rolling fBm hills,
    /// plus a cliff where a wavy line crosses the world.
    pub fn height_at(&self, x: f32, z: f32) -> f32 {
        self.height_with_cliff_at(x, z, self.cliff_line(x))
    }

    /// `height_at` for a known `cliff_line(x)`, which generation works out
    /// once per column instead of once per sample.
    fn height_with_cliff_at(&self, x: f32, z: f32, cliff_line: f32) -> f32 {
        let scale = 1.0 / f64::from(self.feature_size);
        let slice = f64::from(self.seed) * 7.31 + 0.5;
        let hills = self.fbm.sample(f64::from(x) * scale, f64::from(z) * scale, slice) as f32;
        // The cliff: a smooth step 24 m wide, high on the −z side of the line.
        let across = ((z - cliff_line) / 12.0).clamp(-1.0, 1.0);
        let step = 0.5 - 0.5 * across * (3.0 - across * across) / 2.0;
        hills * self.height + step * self.cliff_height
    }
    // ANCHOR_END: height

    /// Where the cliff runs: z as a function of x, wandering across the
    /// middle in long curves, with a ragged edge from a line of noise.
    pub fn cliff_line(&self, x: f32) -> f32 {
        let ragged = 12.0 * crate::noise::perlin3(f64::from(x) / 23.0, 0.5, f64::from(self.seed)) as f32;
        self.extent() * 0.5 - 140.0 + 90.0 * (x / 260.0).sin() + 40.0 * (x / 97.0).cos() + ragged
    }
}

/// A height field being generated a band of rows at a time: all at once
/// on the desktop, a band between two of a browser page's tasks there
/// (see [`crate::TerrainData::prepare`]).
pub struct HeightRows {
    pub settings: TerrainSettings,
    /// Samples a side, and so rows in all.
    pub size: usize,
    /// Where the cliff runs, worked out once per column.
    cliff: Vec<f32>,
    heights: Vec<f32>,
}

impl HeightRows {
    pub fn new(settings: TerrainSettings) -> Self {
        let size = settings.samples() as usize;
        let cliff = (0..size).map(|x| settings.cliff_line(x as f32 * settings.spacing)).collect();
        Self { settings, size, cliff, heights: Vec::with_capacity(size * size) }
    }

    /// Rows sampled so far.
    pub fn done(&self) -> usize {
        self.heights.len() / self.size
    }

    // ANCHOR: generate
    /// Samples the next `count` rows (fewer at the end). Every sample is
    /// independent of the others, so `map_bands` gives each CPU core a band
    /// of the rows and joins the bands in order.
    pub fn add(&mut self, count: usize) {
        let (size, first) = (self.size, self.done());
        let count = count.min(size - first);
        let (settings, cliff) = (&self.settings, &self.cliff);
        let band = common::parallel::map_bands(count, |rows| {
            let mut band = Vec::with_capacity(rows.len() * size);
            for z in rows.map(|row| first + row) {
                for (x, &cliff_line) in cliff.iter().enumerate() {
                    let (wx, wz) = (x as f32 * settings.spacing, z as f32 * settings.spacing);
                    band.push(settings.height_with_cliff_at(wx, wz, cliff_line));
                }
            }
            band
        });
        self.heights.extend(band);
    }
    // ANCHOR_END: generate

    /// The field, once every row is sampled (rows not sampled yet are
    /// sampled now).
    pub fn finish(mut self) -> HeightField {
        self.add(self.size);
        HeightField { settings: self.settings, size: self.size as u32, heights: self.heights }
    }
}

/// Heights on a square grid, row by row (z), `size` samples a side.
pub struct HeightField {
    pub settings: TerrainSettings,
    pub size: u32,
    pub heights: Vec<f32>,
}

impl HeightField {
    /// Samples every grid point, all rows at once.
    pub fn generate(settings: TerrainSettings) -> Self {
        HeightRows::new(settings).finish()
    }

    /// Height at grid point (x, z), clamped to the edge of the field.
    pub fn height(&self, x: i64, z: i64) -> f32 {
        let last = i64::from(self.size) - 1;
        self.heights[(z.clamp(0, last) * i64::from(self.size) + x.clamp(0, last)) as usize]
    }

    // ANCHOR: normal
    /// The surface normal at grid point (x, z) by central differences:
    /// the slope along x is (h(x+1) − h(x−1)) / 2s, along z likewise, and
    /// (−∂h/∂x, 1, −∂h/∂z) is perpendicular to both. Because it reads the
    /// whole field, a point on a chunk border gets the same normal from
    /// either chunk.
    pub fn normal(&self, x: i64, z: i64) -> Vec3 {
        let two_s = 2.0 * self.settings.spacing;
        let dx = (self.height(x + 1, z) - self.height(x - 1, z)) / two_s;
        let dz = (self.height(x, z + 1) - self.height(x, z - 1)) / two_s;
        Vec3::new(-dx, 1.0, -dz).normalize()
    }
    // ANCHOR_END: normal

    /// Height anywhere in the world, interpolated between grid points.
    pub fn height_at(&self, x: f32, z: f32) -> f32 {
        let (gx, gz) = (x / self.settings.spacing, z / self.settings.spacing);
        let (x0, z0) = (gx.floor(), gz.floor());
        let (fx, fz) = (gx - x0, gz - z0);
        let (x0, z0) = (x0 as i64, z0 as i64);
        let top = self.height(x0, z0) * (1.0 - fx) + self.height(x0 + 1, z0) * fx;
        let bottom = self.height(x0, z0 + 1) * (1.0 - fx) + self.height(x0 + 1, z0 + 1) * fx;
        top * (1.0 - fz) + bottom * fz
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn small() -> TerrainSettings {
        TerrainSettings { chunks_per_side: 2, ..Default::default() }
    }

    #[test]
    fn generation_is_deterministic_and_matches_height_at() {
        let a = HeightField::generate(small());
        let b = HeightField::generate(small());
        assert_eq!(a.heights, b.heights);
        assert_eq!(a.size, 129);
        assert_eq!(a.height(37, 91), small().height_at(37.0, 91.0));
        let other_seed = HeightField::generate(TerrainSettings { seed: 8, ..small() });
        assert_ne!(a.heights, other_seed.heights);
    }

    #[test]
    fn rows_added_a_few_at_a_time_give_the_same_field() {
        let whole = HeightField::generate(small());
        for step in [1, 7, 50, 1000] {
            let mut rows = HeightRows::new(small());
            let mut calls = 0;
            while rows.done() < rows.size {
                rows.add(step);
                calls += 1;
            }
            assert_eq!(calls, rows.size.div_ceil(step), "{step} rows a step");
            assert_eq!(rows.finish().heights, whole.heights, "{step} rows a step");
        }
    }

    #[test]
    fn flat_ground_has_upright_normals_and_slopes_tilt_them() {
        let mut field = HeightField::generate(small());
        field.heights.iter_mut().for_each(|h| *h = 0.0);
        assert_eq!(field.normal(10, 10), Vec3::Y);
        // A ramp rising 1 m per metre along x leans its normal 45° towards -x.
        for z in 0..field.size {
            for x in 0..field.size {
                field.heights[(z * field.size + x) as usize] = x as f32;
            }
        }
        let n = field.normal(10, 10);
        assert!(n.distance(Vec3::new(-1.0, 1.0, 0.0).normalize()) < 1e-6, "{n}");
    }

    #[test]
    fn the_cliff_is_steep() {
        let settings = TerrainSettings::default();
        for x in [100.0, 1000.0, 2048.0, 3900.0] {
            let line = settings.cliff_line(x);
            let rise = settings.height_at(x, line - 12.0) - settings.height_at(x, line + 12.0);
            // Across 24 m the cliff adds its full height on top of the hills.
            assert!(rise > 0.8 * settings.cliff_height, "only {rise} m at x = {x}");
        }
    }

    #[test]
    fn bilinear_height_hits_grid_points() {
        let field = HeightField::generate(small());
        assert_eq!(field.height_at(12.0, 30.0), field.height(12, 30));
        let between = field.height_at(12.5, 30.0);
        assert!((between - 0.5 * (field.height(12, 30) + field.height(13, 30))).abs() < 1e-4);
    }
}
