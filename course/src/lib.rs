//! The course: every chapter of the book, in book order, each as one
//! [`Record`] made from its `impl Chapter` (name, title, views, snapshot
//! time, browser tolerance, whether it prepares in steps). The snapshot
//! test, the browser build and its test, the diagrams and xtask read
//! chapters from here, so a fact about a chapter is written once, in the
//! chapter, or here for what only the course needs (its part of the
//! book, the README's picture and line). Adding a chapter adds one line
//! to [`chapters`] and one dependency to this crate's `Cargo.toml`; the
//! README's chapter table and the book's summary are written from here
//! (`cargo xtask book`), and a test fails when they are not.

use std::process::ExitCode;

use common::chapter::{About, Runnable};
use common::headless::{Offscreen, draw_frame, read_texture};
use common::{Camera, Chapter, Gpu, GpuNeeds, PassCount, PassTimer, Target, Tolerance, View, anyhow, image};

/// Every chapter, in book order: its type, the part of the book it is in,
/// the view the README shows, and what it teaches in a line (the README's
/// chapter table and the book's summary are made from these).
pub fn chapters() -> Vec<Record> {
    vec![
        record::<triangle::Triangle>(
            &BASICS,
            "default",
            "buffers, WGSL, a render pipeline, per-vertex colour interpolation",
        ),
        record::<camera::CameraChapter>(
            &BASICS,
            "default",
            "model/view/projection, fly camera, primitives, depth buffer",
        ),
        record::<terrain::TerrainChapter>(
            &MARS,
            "default",
            "improved Perlin noise, fBm, seamless normals, frustum culling, a quadtree of levels of detail that morph into each other (CDLOD)",
        ),
        record::<fog::FogChapter>(
            &MARS,
            "default",
            "exponential distance fog matched to the sky, far plane at the opaque distance, WGSL modules",
        ),
        record::<instancing::InstancingChapter>(
            &MARS,
            "default",
            "one instanced draw for up to a million rocks, against one draw per rock; the first compute shader culls and grades them, with indirect draws; the Mars plain so far",
        ),
        record::<skybox::SkyboxChapter>(
            &MARS,
            "dusk",
            "day and night cube maps, a turning sky whose sun is the light, fog that follows the sky",
        ),
        record::<water::WaterChapter>(
            &MARS,
            "default",
            "reflection and refraction pictures, clip distances, Fresnel, DuDv ripples, soft shores, sine waves: the Mars scene, complete",
        ),
        record::<lighting::LightingChapter>(
            &CITY,
            "night",
            "a city by day and night: Lambert, Phong and Blinn-Phong; flat, Gouraud and Phong shading; point and spot lights; 339 lights culled per cluster; HDR, bloom, ACES",
        ),
        record::<textures::TexturesChapter>(
            &CITY,
            "night",
            "the city textured: UVs and texel density, samplers and GPU mipmaps, sRGB, OBJ + MTL models (`--model PATH.obj` shows yours), tangents and normal maps",
        ),
        record::<shadows::ShadowsChapter>(
            &ENGINE,
            "default",
            "a side-scroller lit by the sun: a shadow map fitted to the view and snapped to texels, depth comparison, slope-scaled and normal-offset bias, hard, PCF, Poisson and PCSS filtering; swept AABB collision, fixed-step physics, parallax layers",
        ),
        record::<voronoi_water::VoronoiWaterChapter>(
            &OCEAN,
            "default",
            "a boat on an endless toon sea: Voronoi diagrams by cones with a depth test and by jump flooding, tiling, separable blur, Sobel edges; a grid that follows the boat in whole cells, a sea periodic in space and time, the boat riding the same waves on the CPU; gradient-texture sunsets, bloom and the boat's shadow from chapters 08 and 10",
        ),
    ]
}

/// A part of the book: its heading in the summary, and the page that opens
/// it (the seed project it rebuilds, what that project did and where it
/// fell short, what the part adds, and the finished scene), as its title in
/// the summary and its file in `book/src/`.
pub struct Part {
    pub title: &'static str,
    pub opening: Option<(&'static str, &'static str)>,
}

// The parts of the book, each after the seed project its chapters rebuild.
// The basics rebuild no one project (chapter 02's camera comes from two),
// so the introduction opens them.
static BASICS: Part = Part { title: "The basics", opening: None };
static MARS: Part = Part { title: "Prehistoric Mars", opening: Some(("The Mars project", "part-mars.md")) };
static CITY: Part = Part { title: "The futuristic city", opening: Some(("The city project", "part-city.md")) };
static ENGINE: Part = Part { title: "The small engine", opening: Some(("The engine project", "part-engine.md")) };
static OCEAN: Part = Part { title: "The ocean", opening: Some(("The ocean project", "part-ocean.md")) };

/// The pages after the last chapter, as (title, file in `book/src/`).
pub const APPENDICES: [(&str, &str); 6] = [
    ("Appendix: Running in the browser", "running-in-the-browser.md"),
    ("Appendix: On a Mac, on Windows and on older OpenGL", "other-systems.md"),
    ("Appendix: Change it and see it change", "shader-panel.md"),
    ("Appendix: The browser, measured", "browser-numbers.md"),
    ("Appendix: Frame rates, the seeds' and ours", "frame-rates.md"),
    ("Glossary: light and its measures", "glossary.md"),
];

/// The chapter called `name` (its package name), if there is one.
pub fn find(name: &str) -> Option<Record> {
    chapters().into_iter().find(|r| r.name == name)
}

/// What the tools know of one chapter, whatever its type.
#[derive(Clone, Copy)]
pub struct Record {
    /// The package name: `cargo run -p NAME`, its page `live/NAME/`.
    pub name: &'static str,
    /// The Rust type that implements `Chapter` (`terrain::demo::TerrainChapter`).
    pub type_name: &'static str,
    /// The book's title for it.
    pub title: &'static str,
    /// The part of the book it belongs to.
    pub part: &'static Part,
    /// The view the README shows as its picture.
    pub figure: &'static str,
    /// What it teaches, in one line.
    pub techniques: &'static str,
    pub views: &'static [View],
    /// The scene time of its snapshots and still pictures.
    pub snapshot_time: f32,
    /// How far its still picture in the browser may be from the native one.
    pub browser_tolerance: Tolerance,
    /// Whether it prepares in steps before its first frame (chapter 03's terrain).
    pub prepares_in_steps: bool,
    /// Whether it finishes its frames with chapter 08's post chain.
    pub post_chain: bool,
    /// What it needs of an adapter (`Chapter::gpu_needs`).
    pub needs: fn() -> GpuNeeds,
    /// The settings each view applies, as the chapter writes them (part of
    /// a frame's fingerprint, `common::fingerprint`).
    pub view_settings: fn(usize) -> String,
    /// Runs it as its binary's `main` does (in a browser, from the page's URL).
    pub run: fn() -> ExitCode,
    /// Makes an instance for `target` on `gpu`.
    pub open: fn(&Gpu, Target) -> anyhow::Result<Box<dyn AnyChapter>>,
}

fn record<C: Chapter>(part: &'static Part, figure: &'static str, techniques: &'static str) -> Record {
    Record {
        name: C::NAME,
        type_name: std::any::type_name::<C>(),
        title: C::TITLE,
        part,
        figure,
        techniques,
        views: C::VIEWS,
        snapshot_time: C::SNAPSHOT_TIME,
        browser_tolerance: C::BROWSER_TOLERANCE,
        prepares_in_steps: C::PREPARES_IN_STEPS,
        post_chain: C::POST_ANTIALIASING,
        needs: C::gpu_needs,
        view_settings: C::view_settings,
        run: common::run::<C>,
        open: |gpu, target| {
            let chapter = About::of::<C>().create(gpu, target, &Default::default())?;
            Ok(Box::new(Instance { chapter, target }))
        },
    }
}

/// The limits of a WebGL2 adapter as the book's pages meet it: WebGL2's
/// guaranteed ones, with textures as large as the terrain's height map
/// (4097 texels a side; desktop browsers give 8192 or more, WebGL2 only
/// promises 2048).
pub fn webgl2_limits() -> common::wgpu::Limits {
    common::wgpu::Limits { max_texture_dimension_2d: 4097, ..common::wgpu::Limits::downlevel_webgl2_defaults() }
}

impl Record {
    /// Whether the chapter draws on WebGL2: its needs are met by an adapter
    /// with no optional feature, no downlevel capability and
    /// [`webgl2_limits`]. (The browser test checks that those draw and the
    /// others refuse by name.)
    pub fn draws_on_webgl2(&self) -> bool {
        self.lacks_on_webgl2().is_empty()
    }

    /// What the chapter needs that such a WebGL2 adapter lacks, each named
    /// as the chapter's refusal names it (`GpuNeeds::missing_on`).
    pub fn lacks_on_webgl2(&self) -> Vec<String> {
        let none = (common::wgpu::Features::empty(), common::wgpu::DownlevelFlags::empty());
        (self.needs)().missing_on(none.0, none.1, &webgl2_limits())
    }

    /// The first view that is a snapshot: the one the browser test and
    /// `bench web` show.
    pub fn first_snapshot_view(&self) -> Option<&'static View> {
        self.views.iter().find(|v| v.snapshot)
    }
}

/// The book's folder for `record`: `NN-name`, NN from its title. The
/// chapter's section lives there: its opening page and its lessons.
pub fn section(record: &Record) -> String {
    let number: String = record.title.chars().take_while(char::is_ascii_digit).collect();
    format!("{number}-{}", record.name)
}

/// The page that opens `record`'s section: `NN-name/index.md`.
pub fn page(record: &Record) -> String {
    format!("{}/index.md", section(record))
}

/// A page of the book under a chapter's opening page, as its title and its
/// file in `book/src/`.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct SubPage {
    pub title: String,
    pub file: String,
}

/// The README's chapter table, made from the records.
pub fn readme_table(chapters: &[Record]) -> String {
    let mut table = String::from("| | chapter | package | technique |\n|---|---|---|---|\n");
    for c in chapters {
        table.push_str(&format!(
            "| <img src=\"tests/snapshots/{}/{}.png\" width=\"200\"> | {} | `{}` | {} |\n",
            c.name, c.figure, c.title, c.name, c.techniques
        ));
    }
    table
}

/// The book's `SUMMARY.md` after its first pages, made from the records: a
/// heading per part, the page that opens the part, a line per chapter with
/// its pages under it (`sub_pages`: its lessons, then its reference pages,
/// as its opening page lists them), then the appendices, unnumbered, after
/// a rule.
pub fn summary_chapters(chapters: &[Record], sub_pages: impl Fn(&Record) -> Vec<SubPage>) -> String {
    let mut text = String::new();
    let mut part: Option<&Part> = None;
    for c in chapters {
        if !part.is_some_and(|p| std::ptr::eq(p, c.part)) {
            part = Some(c.part);
            text.push_str(&format!("\n# {}\n\n", c.part.title));
            if let Some((title, file)) = c.part.opening {
                text.push_str(&format!("- [{title}]({file})\n"));
            }
        }
        text.push_str(&format!("- [{}]({})\n", c.title, page(c)));
        for sub in sub_pages(c) {
            text.push_str(&format!("    - [{}]({})\n", sub.title, sub.file));
        }
    }
    text.push_str("\n---\n\n");
    for (title, file) in APPENDICES {
        text.push_str(&format!("[{title}]({file})\n"));
    }
    text
}

/// A chapter instance, whatever its type, as the tests drive it.
pub trait AnyChapter {
    /// As the overlay does: the view's settings, and a preset's camera.
    fn show(&mut self, view: usize);
    fn reset_camera(&mut self, view: usize);
    fn camera(&mut self) -> Option<Camera>;
    fn set_camera(&mut self, camera: Camera);
    /// Renders `view` at `time` offscreen; returns the picture and the
    /// passes it drew (timed on the GPU, then on the CPU).
    fn render(&mut self, gpu: &Gpu, view: usize, time: f32) -> anyhow::Result<(image::RgbaImage, Vec<&'static str>)> {
        self.render_counted(gpu, view, time).map(|(image, passes, _)| (image, passes))
    }
    /// [`AnyChapter::render`], and what each pass drew as the chapter
    /// counted it (`Frame::drawn`).
    fn render_counted(
        &mut self,
        gpu: &Gpu,
        view: usize,
        time: f32,
    ) -> anyhow::Result<(image::RgbaImage, Vec<&'static str>, Vec<PassCount>)>;
}

/// Any chapter, made and driven through the runners' own [`Runnable`].
struct Instance {
    chapter: Box<dyn Runnable>,
    target: Target,
}

impl AnyChapter for Instance {
    fn show(&mut self, view: usize) {
        self.chapter.select_view(view);
    }

    fn reset_camera(&mut self, view: usize) {
        self.chapter.reset_camera(view);
    }

    fn camera(&mut self) -> Option<Camera> {
        self.chapter.camera_mut().copied()
    }

    fn set_camera(&mut self, camera: Camera) {
        if let Some(c) = self.chapter.camera_mut() {
            *c = camera;
        }
    }

    fn render_counted(
        &mut self,
        gpu: &Gpu,
        view: usize,
        time: f32,
    ) -> anyhow::Result<(image::RgbaImage, Vec<&'static str>, Vec<PassCount>)> {
        debug_assert!(view < self.chapter.about().views.len());
        let offscreen = Offscreen::new(&gpu.device, self.target);
        let timer = PassTimer::off();
        let counted = draw_frame(
            gpu,
            self.chapter.as_mut(),
            &offscreen.view,
            (time, view),
            common::Antialiasing::default(),
            &timer,
        );
        let mut passes = timer.take_labels();
        passes.extend(timer.take_cpu().into_iter().map(|(label, _)| label));
        Ok((read_texture(gpu, &offscreen.texture)?, passes, counted))
    }
}
