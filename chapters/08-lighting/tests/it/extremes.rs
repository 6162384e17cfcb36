//! The overlay's sliders at their ends: no light at all and the most
//! lights under every shading model; the bloom's threshold, strength and
//! spread at their limits under every display; exposure at both ends; and
//! a 1 × 1 target. Nothing may produce a validation error or a NaN.

use common::headless::{OFFSCREEN_FORMAT, Offscreen, draw_frame, read_floats};
use common::{Chapter, Gpu, PassTimer, Target, chapter::view_index};
use lighting::{Display, LightCount, LightTerm, LightingChapter, MAX_LIGHTS, Settings, Shading};

/// The night city drawn into a `width` × `height` target, over and over
/// with other settings: the city (its countryside too) is built once, as a
/// learner's window builds it once and then moves sliders.
struct Night {
    chapter: LightingChapter,
    offscreen: Offscreen,
}

impl Night {
    fn new(gpu: &Gpu, (width, height): (u32, u32)) -> Self {
        let target = Target { format: OFFSCREEN_FORMAT, width, height, samples: 1 };
        let mut chapter = LightingChapter::new(gpu, target, ()).unwrap();
        chapter.select_view(view_index::<LightingChapter>("night").unwrap());
        Self { chapter, offscreen: Offscreen::new(&gpu.device, target) }
    }

    /// Draws one frame with `settings`, inside a validation error scope,
    /// and checks the bloom for NaNs.
    fn draw(&mut self, gpu: &Gpu, settings: Settings, case: &str) {
        self.chapter.settings = settings;
        let Self { chapter, offscreen } = self;
        gpu.catch_validation(|| {
            draw_frame(gpu, chapter, &offscreen.view, (6.0, 1), Default::default(), &PassTimer::off())
        })
        .unwrap_or_else(|e| panic!("{case}: {e}"));
        let bloom = read_floats(gpu, chapter.post.bloom().output().texture()).unwrap();
        assert!(bloom.iter().flatten().all(|v| v.is_finite()), "{case}: the bloom holds a NaN or an infinity");
    }
}

#[test]
fn sliders_at_their_ends_draw_without_errors_or_nans() {
    let gpu = Gpu::headless(LightingChapter::gpu_needs()).expect("an adapter (lavapipe will do)");
    let night = Settings::NIGHT;
    let mut small = Night::new(&gpu, (96, 54));
    for lights in [LightCount::First(0), LightCount::First(MAX_LIGHTS), LightCount::City] {
        // The countryside only with the city's own lights (its billboard
        // adds three): flat and Gouraud shading light every vertex, and
        // the countryside's, nearly all outside the view and so outside
        // every cluster, visit every light, which made the most lights
        // take 24 s of this test's 37.
        let countryside = lights == LightCount::City;
        for shading in [Shading::Flat, Shading::Gouraud, Shading::Phong] {
            let settings = Settings { lights, shading, countryside, ..night };
            small.draw(&gpu, settings, &format!("{lights:?}, {shading:?}"));
        }
    }
    for (threshold, strength, spread, exposure) in [(0.2, 2.0, 0.0, 0.1), (4.0, 0.0, 1.0, 4.0), (0.2, 2.0, 1.0, 4.0)] {
        for display in [
            Display::Scene,
            Display::Term(LightTerm::Ambient),
            Display::Term(LightTerm::Diffuse),
            Display::Term(LightTerm::Specular),
            Display::BloomOnly,
            Display::LightTiles,
        ] {
            let mut s = Settings { display, exposure, ..night };
            (s.bloom.threshold, s.bloom.strength, s.bloom.spread) = (threshold, strength, spread);
            small.draw(&gpu, s, &format!("{display:?}, bloom {threshold}/{strength}/{spread}, exposure {exposure}"));
        }
    }
    let mut one_pixel = Night::new(&gpu, (1, 1));
    for lights in [LightCount::City, LightCount::First(MAX_LIGHTS)] {
        one_pixel.draw(&gpu, Settings { lights, ..night }, &format!("1 × 1, {lights:?}"));
    }
}
