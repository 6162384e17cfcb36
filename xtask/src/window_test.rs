//! The window test: every chapter in a real window on a virtual X server,
//! driven the way people drive windows, with `xdotool`. For each chapter it
//! reads the window's pixels back (the scene must be drawn), resizes the
//! window through 1×1 and back, minimises and restores it (three times
//! each), drags with the mouse and checks that the camera turned, holds a
//! key and clicks the overlay and checks that the camera stops once the key
//! is let go, watches memory over `leak::WATCHED_FRAMES` frames, then closes the window with
//! Esc. One chapter runs once more with the shader panel open
//! (`drive_panel`). Any panic, wgpu validation error, non-zero exit, frame
//! that never comes, or memory that grows frame after frame or cycle after
//! cycle (`common/src/leak.rs`, compiled here too) fails it.
//!
//! What cannot be seen in pixels (frames drawn, the surface's size, the
//! camera) the chapter reports through its hidden `--probe FILE` flag.

use std::path::{Path, PathBuf};
use std::process::{Child, Command, Stdio};
use std::time::{Duration, Instant};

use anyhow::{Context as _, bail, ensure};

use crate::{chapter_names, quiet_env, target_dir};

/// How memory growth is judged, and its bounds: the chapters' own file,
/// which uses nothing but `std`, so that the bounds are written once.
#[path = "../../common/src/leak.rs"]
mod leak;

/// The window's size, and how long any one step may take: a frame of the
/// water chapter takes over a second on a software rasteriser in a debug build.
const SIZE: (u32, u32) = (640, 360);
const STEP_TIMEOUT: Duration = Duration::from_secs(90);
/// Resizes through 1×1 and minimise/restore cycles per chapter (each costs
/// two frames, seconds each for the terrain chapters on a software
/// rasteriser): `leak::CYCLES` says why three.
const CYCLES: usize = leak::CYCLES;

/// x, y, z, yaw and pitch, as the probe reports them; `None` for chapters
/// without a camera.
type Pose = Option<[f32; 5]>;

/// What the chapter last wrote to its probe file.
#[derive(Clone, Debug, PartialEq)]
struct Probe {
    drawn: u64,
    surface: (u32, u32),
    /// The overlay has the keyboard (a text field is being edited).
    typing: bool,
    /// The process's resident memory, its allocator's live bytes and the
    /// GPU's buffers and textures, in bytes (`None` where the chapter cannot
    /// say).
    memory: Option<u64>,
    heap: Option<u64>,
    gpu: Option<u64>,
    camera: Pose,
}

impl Probe {
    fn parse(line: &str) -> Option<Self> {
        let field = |name: &str| line.split_whitespace().find_map(|w| w.strip_prefix(name));
        let drawn = field("drawn=")?.parse().ok()?;
        let (w, h) = field("surface=")?.split_once('x')?;
        let camera_text = line.split_once("camera=")?.1.trim();
        let camera = if camera_text == "none" {
            None
        } else {
            let values: Vec<f32> = camera_text.split_whitespace().filter_map(|v| v.parse().ok()).collect();
            Some(values.try_into().ok()?)
        };
        let typing = field("typing=")? == "1";
        let bytes = |name: &str| field(name).and_then(|v| v.parse().ok());
        let (memory, heap, gpu) = (bytes("memory="), bytes("heap="), bytes("gpu="));
        Some(Self { drawn, surface: (w.parse().ok()?, h.parse().ok()?), typing, memory, heap, gpu, camera })
    }
}

/// A virtual X server with a window manager (without one, nothing can be
/// minimised), torn down when dropped.
struct Display {
    name: String,
    server: Child,
    manager: Child,
}

impl Display {
    fn start() -> anyhow::Result<Self> {
        // Threads starting displays at once must not pick the same number.
        static TAKEN: std::sync::Mutex<Vec<u32>> = std::sync::Mutex::new(Vec::new());
        let mut taken = TAKEN.lock().unwrap_or_else(|e| e.into_inner());
        let free = |n: &u32| !taken.contains(n) && !Path::new(&format!("/tmp/.X{n}-lock")).exists();
        let number = (90..190).find(free).context("no free display")?;
        taken.push(number);
        drop(taken);
        let name = format!(":{number}");
        let server = Command::new("Xvfb")
            .args([name.as_str(), "-screen", "0", "1024x768x24", "-nolisten", "tcp"])
            .stderr(Stdio::null())
            .spawn()
            .context("cannot start Xvfb")?;
        let deadline = Instant::now() + Duration::from_secs(10);
        while !Path::new(&format!("/tmp/.X11-unix/X{number}")).exists() {
            ensure!(Instant::now() < deadline, "Xvfb did not start");
            std::thread::sleep(Duration::from_millis(50));
        }
        let manager = Command::new("openbox")
            .arg("--sm-disable")
            .env("DISPLAY", &name)
            .stdout(Stdio::null())
            .stderr(Stdio::null())
            .spawn()
            .context("cannot start openbox")?;
        std::thread::sleep(Duration::from_millis(500));
        Ok(Self { name, server, manager })
    }

    fn xdotool(&self, args: &[&str]) -> anyhow::Result<String> {
        let output = Command::new("xdotool").args(args).env("DISPLAY", &self.name).output().context("xdotool")?;
        ensure!(
            output.status.success(),
            "xdotool {} failed: {}",
            args.join(" "),
            String::from_utf8_lossy(&output.stderr)
        );
        Ok(String::from_utf8_lossy(&output.stdout).trim().to_string())
    }
}

impl Drop for Display {
    fn drop(&mut self) {
        let _ = self.manager.kill();
        let _ = self.server.kill();
        let _ = self.manager.wait();
        let _ = self.server.wait();
    }
}

/// One chapter running in a window on `display`.
struct Session<'d> {
    display: &'d Display,
    chapter: String,
    child: Child,
    probe: PathBuf,
    log: PathBuf,
    window: String,
}

impl<'d> Session<'d> {
    fn start(display: &'d Display, chapter: &str, dir: &Path, extra: &[&str]) -> anyhow::Result<Self> {
        let probe = dir.join(format!("{chapter}.probe"));
        let log = dir.join(format!("{chapter}.log"));
        let _ = std::fs::remove_file(&probe);
        let child = Command::new(target_dir().join("debug").join(chapter))
            .args(extra)
            .args(["--size", &format!("{}x{}", SIZE.0, SIZE.1), "--probe"])
            .arg(&probe)
            .env("DISPLAY", &display.name)
            .env_remove("WAYLAND_DISPLAY")
            .envs(quiet_env())
            // winit warns about Xvfb's missing XSETTINGS and 0 mm screen size.
            .env("RUST_LOG", "error")
            .stdout(Stdio::null())
            .stderr(std::fs::File::create(&log)?)
            .spawn()
            .with_context(|| format!("cannot start {chapter}"))?;
        let mut session = Self { display, chapter: chapter.into(), child, probe, log, window: String::new() };
        session.wait_for("its first frames", |p| p.drawn >= 2)?;
        let pid = session.child.id().to_string();
        session.window = display.xdotool(&["search", "--sync", "--pid", &pid, "--name", "From Triangle"])?;
        session.window = session.window.lines().next().unwrap_or_default().to_string();
        Ok(session)
    }

    /// The window's pixels as X shows them (what the chapter presented,
    /// overlay included), read with `xwd` and returned as RGB rows.
    fn picture(&self) -> anyhow::Result<(u32, u32, Vec<[u8; 3]>)> {
        let output = Command::new("xwd")
            .args(["-silent", "-id", &self.window])
            .env("DISPLAY", &self.display.name)
            .output()
            .context("xwd")?;
        ensure!(output.status.success(), "xwd failed: {}", String::from_utf8_lossy(&output.stderr));
        parse_xwd(&output.stdout).with_context(|| format!("{}: cannot read xwd's picture", self.chapter))
    }

    /// The picture right of the overlay's panel shows the scene: more than
    /// one colour there (a window that presents nothing, or the clear
    /// colour alone, is one colour). Returns how many it found.
    fn scene_is_drawn(&self) -> anyhow::Result<usize> {
        let (width, height, pixels) = self.picture()?;
        let mut colours: Vec<[u8; 3]> = (0..height)
            .flat_map(|y| (width * 3 / 4..width).map(move |x| (x, y)))
            .map(|(x, y)| pixels[(y * width + x) as usize])
            .collect();
        colours.sort_unstable();
        colours.dedup();
        ensure!(
            colours.len() >= 2,
            "{}: the window's right quarter is one colour ({:?}): the scene was not drawn",
            self.chapter,
            colours.first()
        );
        Ok(colours.len())
    }

    fn read(&self) -> Option<Probe> {
        Probe::parse(&std::fs::read_to_string(&self.probe).ok()?)
    }

    /// Waits until the probe satisfies `done`, failing if the chapter exits
    /// or `STEP_TIMEOUT` passes.
    fn wait_for(&mut self, what: &str, done: impl Fn(&Probe) -> bool) -> anyhow::Result<Probe> {
        let deadline = Instant::now() + STEP_TIMEOUT;
        loop {
            if let Some(probe) = self.read().filter(&done) {
                return Ok(probe);
            }
            if let Some(status) = self.child.try_wait()? {
                bail!("{} exited ({status}) while waiting for {what}:\n{}", self.chapter, self.log_tail());
            }
            ensure!(
                Instant::now() < deadline,
                "{}: timed out waiting for {what}; last probe {:?}",
                self.chapter,
                self.read()
            );
            std::thread::sleep(Duration::from_millis(20));
        }
    }

    /// Waits for `frames` more frames to be drawn; returns the last probe.
    fn frames(&mut self, frames: u64, what: &str) -> anyhow::Result<Probe> {
        let start = self.read().map_or(0, |p| p.drawn);
        self.wait_for(what, |p| p.drawn >= start + frames)
    }

    fn x(&self, args: &[&str]) -> anyhow::Result<String> {
        let mut all: Vec<&str> = args.to_vec();
        // Commands that act on a window take it right after the command.
        if matches!(args[0], "windowsize" | "windowminimize" | "windowactivate" | "windowfocus") {
            all.insert(1, &self.window);
            if args[0] == "windowfocus" || args[0] == "windowactivate" {
                all.insert(1, "--sync");
            }
        }
        self.display.xdotool(&all)
    }

    fn log_tail(&self) -> String {
        let text = std::fs::read_to_string(&self.log).unwrap_or_default();
        let lines: Vec<&str> = text.lines().collect();
        lines[lines.len().saturating_sub(25)..].join("\n")
    }

    /// Resizes the window through 1×1 and back `CYCLES` times (or
    /// `leak::MORE_CYCLES` more); fails when memory grew by more than its
    /// bound a cycle (`leak::CYCLE_BOUND`, `leak::GPU_CYCLE_BOUND`).
    fn resize_through_one_pixel(&mut self) -> anyhow::Result<()> {
        let (w, h) = (SIZE.0.to_string(), SIZE.1.to_string());
        let mut at_full_size = vec![self.frames(1, "a frame before resizing")?];
        let mut cycles = CYCLES;
        while at_full_size.len() <= cycles {
            self.x(&["windowsize", "1", "1"])?;
            self.wait_for("a 1×1 frame", |p| p.surface == (1, 1))?;
            self.x(&["windowsize", &w, &h])?;
            at_full_size.push(self.wait_for("a full-size frame again", |p| p.surface == SIZE)?);
            if at_full_size.len() == CYCLES + 1 && self.grows_too_much_a_cycle(&at_full_size) {
                cycles += leak::MORE_CYCLES;
            }
        }
        self.grows_less_than_a_leak_a_cycle("resize through 1×1", &at_full_size)
    }

    /// Minimises and restores the window `CYCLES` times: nothing may be
    /// drawn while minimised (watched for a few of the chapter's own frame
    /// times, so that a chapter whose frames take a second cannot pass by
    /// being slow), and memory may not grow by more than its bound a cycle.
    fn minimise_and_restore(&mut self) -> anyhow::Result<()> {
        let frame = self.frame_time()?;
        // A frame in flight may still finish; after that, nothing is drawn:
        // a chapter still drawing would draw two more in three frame times.
        let settle = Duration::from_millis(200).max(frame * 3 / 2);
        let watch = Duration::from_millis(300).max(3 * frame);
        let mut shown = vec![self.frames(1, "a frame before minimising")?];
        let mut cycles = CYCLES;
        while shown.len() <= cycles {
            self.x(&["windowminimize"])?;
            std::thread::sleep(settle);
            let hidden = self.read().map_or(0, |p| p.drawn);
            std::thread::sleep(watch);
            let still = self.read().map_or(0, |p| p.drawn);
            ensure!(
                still <= hidden + 1,
                "{} kept drawing while minimised ({hidden} → {still} frames in {:.1} s, frames take {:.2} s)",
                self.chapter,
                watch.as_secs_f64(),
                frame.as_secs_f64()
            );
            self.x(&["windowactivate"])?;
            shown.push(self.frames(1, "a frame after restoring")?);
            if shown.len() == CYCLES + 1 && self.grows_too_much_a_cycle(&shown) {
                cycles += leak::MORE_CYCLES;
            }
        }
        self.grows_less_than_a_leak_a_cycle("minimise and restore", &shown)
    }

    /// How long the chapter's frames take now: the mean of two.
    fn frame_time(&mut self) -> anyhow::Result<Duration> {
        let start = self.frames(1, "a frame to start timing at")?;
        let began = Instant::now();
        let end = self.frames(2, "two frames to time")?;
        Ok(began.elapsed() / (end.drawn - start.drawn).max(1) as u32)
    }

    /// Whether memory read in the same state before each cycle and after
    /// the last (`readings`) grew by more than its bound a cycle.
    fn grows_too_much_a_cycle(&self, readings: &[Probe]) -> bool {
        MEASURED.iter().any(|m| {
            let values: Option<Vec<u64>> = readings.iter().map(m.read).collect();
            values.as_deref().and_then(leak::growth_per_cycle).is_some_and(|growth| growth > m.per_cycle)
        })
    }

    /// Fails when memory read in the same state before each cycle and after
    /// the last (`readings`) grew by more than its bound a cycle (the
    /// median: a first cycle that fills a cache does not count).
    fn grows_less_than_a_leak_a_cycle(&self, cycle: &str, readings: &[Probe]) -> anyhow::Result<()> {
        for Measured { what, read, per_cycle, .. } in MEASURED {
            let values: Option<Vec<u64>> = readings.iter().map(read).collect();
            let Some(growth) = values.as_deref().and_then(leak::growth_per_cycle) else { continue };
            self.log_memory(&format!("{cycle}: {what} {growth:+.0} bytes a cycle, read {values:?}"));
            ensure!(
                growth <= per_cycle,
                "{}: {what} grew by {:.0} KB a {cycle} (the median of {}; more than {:.0} KB): a leak; read {values:?}",
                self.chapter,
                growth / 1024.0,
                readings.len() - 1,
                per_cycle / 1024.0
            );
        }
        Ok(())
    }

    /// Adds a line to the chapter's memory log, beside its probe: what the
    /// tests read and concluded, for when one fails.
    fn log_memory(&self, line: &str) {
        use std::io::Write as _;
        if let Ok(mut file) =
            std::fs::OpenOptions::new().create(true).append(true).open(self.probe.with_extension("memory"))
        {
            let _ = writeln!(file, "{line}");
        }
    }

    /// Drags across the scene; returns (camera before, camera after).
    fn drag(&mut self) -> anyhow::Result<(Pose, Pose)> {
        self.x(&["windowfocus"])?;
        let before = self.frames(1, "a frame before the drag")?.camera;
        self.x(&["mousemove", "--window", &self.window, "460", "260"])?;
        self.x(&["mousedown", "1"])?;
        for _ in 0..12 {
            self.x(&["mousemove_relative", "--", "10", "3"])?;
            std::thread::sleep(Duration::from_millis(30));
        }
        self.x(&["mouseup", "1"])?;
        let after = self.frames(2, "frames after the drag")?.camera;
        Ok((before, after))
    }

    /// Holds W, clicks into the overlay's time field while holding it (so
    /// the overlay has the keyboard when the key comes up), lets go; returns
    /// the camera while held, and two cameras after the release, a few
    /// frames apart.
    fn hold_key(&mut self) -> anyhow::Result<[Pose; 3]> {
        self.x(&["windowfocus"])?;
        let start = self.frames(1, "a frame before the key")?.camera;
        self.x(&["keydown", "w"])?;
        let held = self.wait_for("the camera to move while W is held", |p| p.camera.is_none() || p.camera != start)?;
        // The time field is the overlay's first row, at the same place in every chapter.
        self.x(&["mousemove", "--window", &self.window, "78", "50"])?;
        self.x(&["click", "1"])?;
        self.wait_for("the overlay's time field to take the keyboard", |p| p.typing)?;
        self.x(&["keyup", "w"])?;
        let released = self.frames(2, "frames after releasing W")?.camera;
        let later = self.frames(3, "more frames after releasing W")?.camera;
        // Click the scene to leave the field.
        self.x(&["mousemove", "--window", &self.window, "500", "300"])?;
        self.x(&["click", "1"])?;
        self.wait_for("the overlay to give the keyboard back", |p| !p.typing)?;
        Ok([held.camera, released, later])
    }

    /// Reads memory at every frame for `leak::WATCHED_FRAMES` frames, after
    /// everything else (so caches are full), and fails when it grew by more
    /// than its bound a frame: the median of the slopes of stretches of
    /// `leak::STRETCH_FRAMES`, which one-off steps cannot move (where the
    /// first frames judge a leak, `leak::MORE_WATCHED_FRAMES` more are read
    /// and all of them judge). Returns the growth of each of [`MEASURED`],
    /// in bytes a frame.
    fn memory_stays_flat(&mut self) -> anyhow::Result<[Option<f64>; 3]> {
        let first = self.frames(1, "a frame before watching memory")?;
        let mut readings = vec![first.clone()];
        self.read_memory_until(&mut readings, first.drawn + leak::WATCHED_FRAMES)?;
        let mut growth = self.growth_per_frame(&readings)?;
        if over_a_bound(&growth) {
            let more = first.drawn + leak::WATCHED_FRAMES + leak::MORE_WATCHED_FRAMES;
            self.read_memory_until(&mut readings, more)?;
            growth = self.growth_per_frame(&readings)?;
        }
        let frames = readings.last().map_or(0, |r| r.drawn) - first.drawn;
        for (m, per_frame) in MEASURED.iter().zip(growth) {
            let Some(per_frame) = per_frame.filter(|&g| g > m.per_frame) else { continue };
            bail!(
                "{}: {}; readings in {}",
                self.chapter,
                leak::describe(m.what, per_frame, frames, m.per_frame),
                self.probe.with_extension("memory").display()
            );
        }
        let gl = std::env::var("WGPU_BACKEND").is_ok_and(|backend| backend.to_ascii_lowercase().contains("gl"));
        let missing = unreported(&growth, gl);
        ensure!(
            missing.is_empty(),
            "{}: the probe reports no count of {} (n/a), which it must: a leak there would go unseen",
            self.chapter,
            missing.join(" or ")
        );
        Ok(growth)
    }

    /// Adds a reading for every frame drawn until `frame`.
    fn read_memory_until(&mut self, readings: &mut Vec<Probe>, frame: u64) -> anyhow::Result<()> {
        let deadline = Instant::now() + STEP_TIMEOUT * 2;
        while readings.last().is_some_and(|last| last.drawn < frame) {
            if let Some(probe) = self.read().filter(|p| readings.last().is_some_and(|last| p.drawn > last.drawn)) {
                readings.push(probe);
            }
            if let Some(status) = self.child.try_wait()? {
                bail!("{} exited ({status}) while memory was watched:\n{}", self.chapter, self.log_tail());
            }
            ensure!(Instant::now() < deadline, "{}: timed out watching memory over frames", self.chapter);
            std::thread::sleep(Duration::from_millis(5));
        }
        Ok(())
    }

    /// The growth a frame of each of [`MEASURED`] that the probe reports,
    /// logged with its readings.
    fn growth_per_frame(&self, readings: &[Probe]) -> anyhow::Result<[Option<f64>; 3]> {
        let mut growth = [None; 3];
        for (m, slot) in MEASURED.iter().zip(&mut growth) {
            let values: Option<Vec<leak::Reading>> = readings.iter().map(|p| Some((p.drawn, (m.read)(p)?))).collect();
            let Some(values) = values else { continue };
            let per_frame = leak::growth_per_frame(&values)
                .with_context(|| format!("{}: too few readings of {} ({values:?})", self.chapter, m.what))?;
            self.log_memory(&format!("{}: {per_frame:+.0} bytes a frame, read {values:?}", m.what));
            *slot = Some(per_frame);
        }
        Ok(growth)
    }

    fn close(mut self) -> anyhow::Result<()> {
        self.x(&["windowfocus"])?;
        self.x(&["key", "Escape"])?;
        let deadline = Instant::now() + STEP_TIMEOUT;
        let status = loop {
            if let Some(status) = self.child.try_wait()? {
                break status;
            }
            ensure!(Instant::now() < deadline, "{}: Esc did not close the window", self.chapter);
            std::thread::sleep(Duration::from_millis(50));
        };
        let log = std::fs::read_to_string(&self.log).unwrap_or_default();
        ensure!(status.success(), "{} exited with {status}:\n{}", self.chapter, self.log_tail());
        for bad in ["panicked", "Validation Error", "wgpu error"] {
            ensure!(!log.contains(bad), "{} reported `{bad}`:\n{}", self.chapter, self.log_tail());
        }
        Ok(())
    }
}

/// The kinds of [`MEASURED`] with no growth because the probe reported
/// them as n/a. Every one must be there, but the GPU's: wgpu counts a
/// device's buffers and textures on Vulkan, Metal and DX12, not on OpenGL
/// (`gl`), which has no allocator to ask.
fn unreported(growth: &[Option<f64>; 3], gl: bool) -> Vec<&'static str> {
    MEASURED
        .iter()
        .zip(growth)
        .enumerate()
        .filter(|(i, (_, g))| g.is_none() && !(gl && *i == 2))
        .map(|(_, (m, _))| m.what)
        .collect()
}

/// A kind of memory the probe reports: its name, how it is read, and the
/// most it may grow by steadily a frame and a cycle (`common/src/leak.rs`).
struct Measured {
    what: &'static str,
    read: fn(&Probe) -> Option<u64>,
    per_frame: f64,
    per_cycle: f64,
}

/// The process's resident set, its live heap and the GPU's buffers and
/// textures.
const MEASURED: [Measured; 3] = [
    Measured {
        what: "the process's memory",
        read: |p| p.memory,
        per_frame: leak::LEAK_BOUND,
        per_cycle: leak::CYCLE_BOUND,
    },
    Measured {
        what: "the live heap",
        read: |p| p.heap,
        per_frame: leak::HEAP_LEAK_BOUND,
        per_cycle: leak::HEAP_CYCLE_BOUND,
    },
    Measured {
        what: "the GPU's buffers and textures",
        read: |p| p.gpu,
        per_frame: leak::LEAK_BOUND,
        per_cycle: leak::GPU_CYCLE_BOUND,
    },
];

/// Whether any of `growth` (one per [`MEASURED`]) is over its bound a frame.
fn over_a_bound(growth: &[Option<f64>; 3]) -> bool {
    MEASURED.iter().zip(growth).any(|(m, g)| g.is_some_and(|g| g > m.per_frame))
}

impl Drop for Session<'_> {
    fn drop(&mut self) {
        if matches!(self.child.try_wait(), Ok(None)) {
            let _ = self.child.kill();
            let _ = self.child.wait();
        }
    }
}

/// Reads an X window dump (`xwd`'s XWDFile: a header of 25 big-endian
/// 32-bit fields, the window's name, a colour map, then the pixels) of
/// a true-colour window into RGB pixels.
fn parse_xwd(bytes: &[u8]) -> anyhow::Result<(u32, u32, Vec<[u8; 3]>)> {
    let field = |i: usize| -> anyhow::Result<u32> {
        let b = bytes.get(4 * i..4 * i + 4).context("short header")?;
        Ok(u32::from_be_bytes([b[0], b[1], b[2], b[3]]))
    };
    let (header, format, width, height) = (field(0)?, field(2)?, field(4)?, field(5)?);
    let (byte_order, bits_per_pixel, bytes_per_line) = (field(7)?, field(11)?, field(12)?);
    let masks = [field(14)?, field(15)?, field(16)?];
    let colours = field(19)?;
    ensure!(format == 2 && bits_per_pixel == 32, "not a 32-bit ZPixmap (format {format}, {bits_per_pixel} bits)");
    let start = header as usize + 12 * colours as usize;
    let mut pixels = Vec::with_capacity((width * height) as usize);
    for y in 0..height as usize {
        for x in 0..width as usize {
            let at = start + y * bytes_per_line as usize + 4 * x;
            let b: [u8; 4] = bytes.get(at..at + 4).context("short pixel data")?.try_into()?;
            let value = if byte_order == 0 { u32::from_le_bytes(b) } else { u32::from_be_bytes(b) };
            pixels.push(masks.map(|mask| ((value & mask) >> mask.trailing_zeros()) as u8));
        }
    }
    Ok((width, height, pixels))
}

/// The chapter whose post chain chapters 08 to 11 share: its window runs
/// with multisampling and FXAA both, so that the post pass's own picture
/// goes through the resizes and the minimising too.
const POST_CHAPTER: &str = "lighting";

/// Runs one chapter through everything; returns a one-line summary.
fn drive(display: &Display, chapter: &str, dir: &Path) -> anyhow::Result<String> {
    let started = Instant::now();
    let extra: &[&str] = if chapter == POST_CHAPTER { &["--antialiasing", "both"] } else { &[] };
    let mut session = Session::start(display, chapter, dir, extra)?;
    let colours = session.scene_is_drawn()?;
    session.resize_through_one_pixel()?;
    session.minimise_and_restore()?;
    let (before, after) = session.drag()?;
    let [held, released, later] = session.hold_key()?;
    if let (Some(before), Some(after)) = (before, after) {
        ensure!(before[3] != after[3] || before[4] != after[4], "{chapter}: dragging did not turn the camera");
        let (Some(released), Some(later)) = (released, later) else { bail!("{chapter}: the camera disappeared") };
        ensure!(held.is_some(), "{chapter}: no camera while W was held");
        ensure!(
            released == later,
            "{chapter}: the camera kept moving after W was released: {released:?} then {later:?}"
        );
    }
    let turned = before.is_some();
    let [process, heap, gpu] = session.memory_stays_flat()?.map(|g| g.map(|g| g / 1024.0));
    session.close()?;
    let gpu = gpu.map_or("no GPU count".into(), |g| format!("GPU {g:+.1} KB"));
    Ok(format!(
        "{chapter}: {colours} colours drawn right of the panel, {CYCLES}× resized through 1×1, {CYCLES}× minimised and restored, {}, memory {:+.1} KB, heap {:+.1} KB and {gpu} a frame, closed cleanly ({:.0} s)",
        if turned { "drag turned the camera, W stopped on release" } else { "no camera to drag" },
        process.unwrap_or_default(),
        heap.unwrap_or_default(),
        started.elapsed().as_secs_f64()
    ))
}

// ANCHOR: shader_panel
/// The chapter whose window also runs with the shader panel open.
const PANEL_CHAPTER: &str = "camera";

/// The shader panel in a window: opened with `--edit`, it has the
/// keyboard; W, A, S and D typed into it (a broken shader for a moment,
/// then erased) never move the camera; the window goes through 1×1 and
/// back with the panel open; Esc leaves the editor, then closes.
fn drive_panel(display: &Display, dir: &Path) -> anyhow::Result<String> {
    let started = Instant::now();
    let mut session = Session::start(display, PANEL_CHAPTER, dir, &["--edit"])?;
    session.x(&["windowfocus"])?;
    let before = session.wait_for("the editor to have the keyboard", |p| p.typing)?.camera;
    // Each key held for frames, as a flyer holds it: a key pressed and let
    // go between two frames would not move a camera anyway.
    for key in ["w", "a", "s", "d"] {
        session.x(&["keydown", key])?;
        session.frames(2, "frames while a key is held in the editor")?;
        session.x(&["keyup", key])?;
    }
    for _ in 0..4 {
        session.x(&["key", "BackSpace"])?;
    }
    let typed = session.frames(2, "frames after erasing")?;
    ensure!(typed.typing, "the editor lost the keyboard while typing");
    ensure!(typed.camera == before, "keys typed into the editor moved the camera: {before:?} then {:?}", typed.camera);
    session.resize_through_one_pixel()?;
    let after = session.frames(2, "frames after resizing")?;
    ensure!(after.camera == before, "the camera moved while the panel was open: {before:?} then {:?}", after.camera);
    session.x(&["windowfocus"])?;
    session.x(&["key", "Escape"])?;
    session.wait_for("the editor to give the keyboard back", |p| !p.typing)?;
    session.close()?;
    Ok(format!(
        "{PANEL_CHAPTER} with the shader panel: typed wasd, camera still, {CYCLES}× resized through 1×1, closed cleanly ({:.0} s)",
        started.elapsed().as_secs_f64()
    ))
}
// ANCHOR_END: shader_panel

/// Builds the chapters, then runs the test for `chosen` chapters (all of
/// them when empty).
pub fn run(chosen: &[String]) -> anyhow::Result<()> {
    let all = chapter_names()?;
    if let Some(bad) = chosen.iter().find(|c| !all.contains(c)) {
        bail!("unknown chapter '{bad}'; the chapters are: {}", all.join(", "));
    }
    crate::cargo(&["build", "--workspace", "--exclude", "xtask", "--bins"])?;
    run_built(chosen)
}

/// [`run`] on chapters already built (`cargo xtask test` builds everything first).
pub fn run_built(chosen: &[String]) -> anyhow::Result<()> {
    let all = chapter_names()?;
    if let Some(bad) = chosen.iter().find(|c| !all.contains(c)) {
        bail!("unknown chapter '{bad}'; the chapters are: {}", all.join(", "));
    }
    if !crate::prerequisites::ensure_window_tools()? {
        println!("\nwindow test skipped: no X server available on this system");
        return Ok(());
    }
    let dir = std::env::temp_dir().join(format!("window-test-{}", std::process::id()));
    std::fs::create_dir_all(&dir)?;
    // Two chapters at a time, each on its own X display (pointer and
    // keyboard focus belong to a display), heaviest first: a software
    // rasteriser draws a frame's vertices on one core.
    let queue: Vec<&String> = all.iter().filter(|c| chosen.is_empty() || chosen.contains(c)).rev().collect();
    let next = std::sync::atomic::AtomicUsize::new(0);
    let failures = std::sync::Mutex::new(Vec::new());
    std::thread::scope(|scope| {
        for _ in 0..2 {
            scope.spawn(|| {
                let display = match Display::start() {
                    Ok(display) => display,
                    Err(error) => return failures.lock().unwrap().push(format!("X display: {error:#}")),
                };
                while let Some(chapter) = queue.get(next.fetch_add(1, std::sync::atomic::Ordering::SeqCst)) {
                    let result = drive(&display, chapter, &dir).and_then(|summary| {
                        if chapter.as_str() != PANEL_CHAPTER {
                            return Ok(summary);
                        }
                        Ok(format!("{summary}\nwindow: {}", drive_panel(&display, &dir)?))
                    });
                    match result {
                        Ok(summary) => println!("window: {summary}"),
                        Err(error) => {
                            println!("window: {chapter} FAILED: {error:#}");
                            failures.lock().unwrap().push(chapter.to_string());
                        }
                    }
                }
            });
        }
    });
    let failures = failures.into_inner().unwrap_or_default();
    ensure!(failures.is_empty(), "the window test failed for {}", failures.join(", "));
    if std::env::var_os("KEEP_WINDOW_LOGS").is_none() {
        let _ = std::fs::remove_dir_all(&dir);
    } else {
        println!("logs in {}", dir.display());
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_memory_count_the_probe_stops_reporting_fails_the_window_test() {
        let all = [Some(1.0), Some(2.0), Some(3.0)];
        assert!(unreported(&all, false).is_empty());
        assert_eq!(unreported(&[Some(1.0), Some(2.0), None], false), ["the GPU's buffers and textures"]);
        assert!(unreported(&[Some(1.0), Some(2.0), None], true).is_empty(), "OpenGL counts no GPU memory");
        assert_eq!(unreported(&[None, Some(2.0), Some(3.0)], true), ["the process's memory"]);
        assert_eq!(unreported(&[Some(1.0), None, None], false), ["the live heap", "the GPU's buffers and textures"]);
    }

    #[test]
    fn probe_lines_parse() {
        let line = "drawn=12 skipped=3 surface=640x360 view=day typing=1 memory=1000 heap=600 gpu=n/a camera=1.0 2.0 3.0 0.5 -0.25\n";
        let probe = Probe::parse(line).unwrap();
        let camera = Some([1.0, 2.0, 3.0, 0.5, -0.25]);
        let expected = Probe {
            drawn: 12,
            surface: (640, 360),
            typing: true,
            memory: Some(1000),
            heap: Some(600),
            gpu: None,
            camera,
        };
        assert_eq!(probe, expected);
        let none = Probe::parse("drawn=1 skipped=0 surface=1x1 view=flat typing=0 camera=none").unwrap();
        assert_eq!(none.camera, None);
        assert!(Probe::parse("drawn=").is_none());
    }
}
