//! From what `CHAPTER --bench` printed to the tables the book includes: the
//! frame rates at the seeds' sizes (`book/src/bench/sizes.md`), and each
//! chapter's tables measured on a machine that has no Rust toolchain, whose
//! raw output `xtask/gpu-bench.sh` saved (`cargo xtask bench saved`). Both
//! the live bench and a saved file go through the same functions, so a
//! number in the book comes from the bench's output by code, never by hand.

use std::path::Path;

use anyhow::{Context as _, bail, ensure};

use crate::SEED_SIZES;

/// What one `CHAPTER --bench --view VIEW --size SIZE` run printed.
pub struct SizeRun {
    pub chapter: String,
    pub view: String,
    /// As the bench takes it: `1280x720`.
    pub size: String,
    pub printed: String,
}

/// Reads runs saved as a `=== CHAPTER VIEW WxH` line, then what that run
/// printed, one after the other (what `xtask/gpu-bench.sh` writes to
/// `sizes.txt`). `file` names the file in errors.
pub fn parse_size_runs(saved: &str, file: &Path) -> anyhow::Result<Vec<SizeRun>> {
    let mut runs: Vec<SizeRun> = Vec::new();
    for (number, line) in saved.lines().enumerate() {
        if let Some(run) = line.strip_prefix("=== ") {
            let fields: Vec<&str> = run.split_whitespace().collect();
            let [chapter, view, size] = fields[..] else {
                bail!("{}:{}: expected `=== CHAPTER VIEW WxH`, found `{line}`", file.display(), number + 1);
            };
            runs.push(SizeRun {
                chapter: chapter.into(),
                view: view.into(),
                size: size.into(),
                printed: String::new(),
            });
        } else if let Some(run) = runs.last_mut() {
            run.printed.push_str(line);
            run.printed.push('\n');
        } else if !line.trim().is_empty() {
            bail!("{}:{}: output before the first `=== CHAPTER VIEW WxH` line", file.display(), number + 1);
        }
    }
    ensure!(!runs.is_empty(), "{}: no `=== CHAPTER VIEW WxH` line", file.display());
    Ok(runs)
}

/// The size whose triangle count the sizes table gives: the one the
/// course's frame budget is set at (1920 × 1080).
const TRIANGLES_AT: (u32, u32) = (1920, 1080);

/// The table of frame rates at [`SEED_SIZES`]: one row per chapter (in the
/// order of `runs`), one column per size, each cell the median frame as the
/// bench printed it and the frames per second it makes, and a last column
/// with the triangles a frame drew at [`TRIANGLES_AT`] (all passes, as the
/// bench counted them; "—" for a run from before it counted). Returns the
/// adapter the runs name ("NVIDIA H200 (Vulkan, DiscreteGpu)") and the
/// markdown table.
pub fn sizes_table(runs: &[SizeRun]) -> anyhow::Result<(String, String)> {
    let mut chapters: Vec<&str> = Vec::new();
    for run in runs {
        if !chapters.contains(&run.chapter.as_str()) {
            chapters.push(&run.chapter);
        }
    }
    let mut heading: Vec<String> = SEED_SIZES.iter().map(|(w, h)| format!("{w} × {h}")).collect();
    heading.push(format!("triangles at {} × {}", TRIANGLES_AT.0, TRIANGLES_AT.1));
    // The frame each row timed (its fingerprint, the same at every size).
    heading.push("frame".to_string());
    let mut table = format!("| chapter | {} |\n|---|{}\n", heading.join(" | "), "---:|".repeat(heading.len()));
    let mut adapter = None;
    for chapter in chapters {
        let mut cells = Vec::new();
        let mut view = "";
        let mut triangles = None;
        for (width, height) in SEED_SIZES {
            let size = format!("{width}x{height}");
            let run = runs
                .iter()
                .find(|r| r.chapter == chapter && r.size == size)
                .with_context(|| format!("no run of {chapter} at {size}"))?;
            view = &run.view;
            let what = format!("{chapter} --view {view} --size {size}");
            // "triangle on ADAPTER, 1920x1080, 10 frames per view"
            let first = run.printed.lines().next().unwrap_or_default();
            let on = first
                .strip_prefix(&format!("{chapter} on "))
                .and_then(|rest| rest.split_once(&format!(", {size}, ")))
                .map(|(on, _)| on)
                .with_context(|| format!("{what}: expected `{chapter} on ADAPTER, {size}, ...`, found `{first}`"))?;
            let first_adapter = adapter.get_or_insert_with(|| on.to_string());
            ensure!(
                on == first_adapter,
                "{what} ran on {on}, the runs before it on {first_adapter}: one table, one adapter"
            );
            let median = frame_median(&run.printed, view).with_context(|| what.clone())?;
            let ms: f64 = median.parse().with_context(|| format!("{what}: median `{median}` is not a number"))?;
            ensure!(ms > 0.0, "{what}: median frame {median} ms");
            cells.push(format!("{median} ms, {:.1} FPS", 1000.0 / ms));
            if (width, height) == TRIANGLES_AT {
                triangles = frame_triangles(&run.printed, view).with_context(|| what.clone())?;
            }
        }
        cells.push(triangles.map_or_else(|| "—".to_string(), thousands));
        let first_run = runs.iter().find(|r| r.chapter == chapter).context("no run")?;
        cells.push(frame_id(&first_run.printed, view).unwrap_or_else(|| "—".to_string()));
        table.push_str(&format!("| {chapter} (`{view}`) | {} |\n", cells.join(" | ")));
    }
    Ok((adapter.context("no runs")?, table))
}

/// The fingerprint of the frame `view`'s rows timed, from the frames
/// section the bench prints last; `None` for a run from before it did.
fn frame_id(printed: &str, view: &str) -> Option<String> {
    let section = &printed[printed.find(crate::figures::FRAMES_HEADING)?..];
    section.lines().find_map(|line| {
        let cells: Vec<&str> = line.split('|').map(str::trim).collect();
        (cells.len() == 6 && cells[1] == view).then(|| cells[2].to_string())
    })
}

/// The median of `view`'s `frame (CPU+GPU)` row, as printed.
fn frame_median<'a>(printed: &'a str, view: &str) -> anyhow::Result<&'a str> {
    printed
        .lines()
        .map(|line| line.split('|').map(str::trim).collect::<Vec<_>>())
        // | view | what | min ms | median ms | p95 ms |
        .find(|cells| (cells.len() == 7 || cells.len() == 8) && cells[1] == view && cells[2] == "frame (CPU+GPU)")
        .map(|cells| cells[4])
        .context("no `frame (CPU+GPU)` row for the view: did the run fail?")
}

/// The line the bench prints above its table of triangles, pass by pass
/// (`common`'s `cli.rs`): `| view | pass | draws | triangles |`.
const TRIANGLES_HEADING: &str = "Triangles drawn in a frame";

/// The triangles `view` drew in a frame, all its passes together, from the
/// bench's table of them; `None` when the output has no rows for it (a run
/// from before the bench counted, or a chapter that counts nothing).
fn frame_triangles(printed: &str, view: &str) -> anyhow::Result<Option<u64>> {
    let Some((_, table)) = printed.split_once(TRIANGLES_HEADING) else { return Ok(None) };
    let mut total = None;
    for line in table.lines().skip(1).skip_while(|l| l.trim().is_empty()).take_while(|l| l.starts_with('|')) {
        let cells: Vec<&str> = line.split('|').map(str::trim).collect();
        // | view | pass | draws | triangles |  → ["", view, pass, draws, triangles, ""]
        if cells.len() != 6 || cells[1] != view {
            continue;
        }
        let count: u64 = cells[4]
            .replace(',', "")
            .parse()
            .with_context(|| format!("`{}` in the table of triangles is not a count", cells[4]))?;
        *total.get_or_insert(0) += count;
    }
    Ok(total)
}

/// `n` with a comma between thousands, as the bench prints counts.
fn thousands(n: u64) -> String {
    let digits = n.to_string();
    let mut text = String::new();
    for (i, digit) in digits.chars().enumerate() {
        if i > 0 && (digits.len() - i).is_multiple_of(3) {
            text.push(',');
        }
        text.push(digit);
    }
    text
}

/// The machine a saved run was made on, from the `gpu.txt` that
/// `xtask/gpu-bench.sh` writes (`nvidia-smi -L`, `nproc`, the CPU's
/// `model name`): "Intel(R) Xeon(R) Processor, 16 threads".
pub fn saved_cpu(gpu_txt: &str, file: &Path) -> anyhow::Result<String> {
    let model = gpu_txt
        .lines()
        .find_map(|l| l.strip_prefix("model name").map(|m| m.trim_start_matches([' ', '\t', ':']).trim()))
        .with_context(|| format!("{}: no `model name` line", file.display()))?;
    let threads: u32 = gpu_txt
        .lines()
        .find_map(|l| l.trim().parse().ok())
        .with_context(|| format!("{}: no line with the thread count (`nproc`)", file.display()))?;
    Ok(format!("{model}, {threads} threads"))
}

/// What the GPU a saved run names in its `gpu.txt` (`GPU 0: NAME (UUID: …)`,
/// from `nvidia-smi -L`) is for drawing, where the tables must say it: the
/// lent machine's H200 is a GH100, a chip made for computing that can draw
/// with little of itself, so its frame times are not a fast graphics card's.
/// `None` for a GPU made for drawing.
pub fn what_the_gpu_is(gpu_txt: &str) -> Option<String> {
    let name = gpu_txt.lines().find_map(|l| l.strip_prefix("GPU 0: "))?.split(" (UUID").next()?.trim();
    let hopper = ["H100", "H200"].iter().any(|chip| name.split_whitespace().any(|word| word == *chip));
    hopper.then(|| {
        format!(
            "The {name} is NVIDIA's GH100 chip, as the H100 is, made for computing rather than drawing: only two of \
             its TPCs (texture processing clusters) can run vertex, geometry and pixel shaders, the rest compute only \
             (NVIDIA, \"NVIDIA Hopper Architecture In-Depth\", 2022). For drawing it is a small GPU, nothing like a \
             desktop graphics card: these times say where a chapter's work goes on this one chip, not how fast a GPU \
             draws the chapter."
        )
    })
}

/// One chapter's saved `CHAPTER --bench --size 1280x720` output, split as
/// the book's page shows it: its first line (which chapter, adapter, size
/// and frames), and the tables and notes after it, less the `time` lines
/// the script's run appended.
pub fn chapter_tables(chapter: &str, saved: &str, file: &Path) -> anyhow::Result<(String, String)> {
    let (first, rest) = saved.split_once('\n').unwrap_or((saved, ""));
    ensure!(
        first.starts_with(&format!("{chapter} on ")),
        "{}: expected its first line to be `{chapter} on ADAPTER, ...` (the bench's), found `{first}`",
        file.display()
    );
    ensure!(rest.contains("| frame (CPU+GPU) |"), "{}: no `frame (CPU+GPU)` row: did the run fail?", file.display());
    // `time` writes "real\t0m1.622s", "user\t...", "sys\t..." after the run.
    let is_time = |line: &str| ["real\t", "user\t", "sys\t"].iter().any(|t| line.starts_with(t));
    let kept: Vec<&str> = rest.lines().filter(|line| !is_time(line)).collect();
    Ok((first.to_string(), format!("{}\n", kept.join("\n").trim())))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Two chapters at the three sizes, as the script saves them (a
    /// second view's row in the first run, which must not be read).
    fn sample() -> String {
        sample_with_triangles(false)
    }

    /// [`sample`], the fog's runs with the bench's table of triangles
    /// (two passes) after the notes, as it prints it, and a table after it.
    fn sample_with_triangles(counted: bool) -> String {
        let mut saved = String::new();
        for (chapter, view, medians) in
            [("triangle", "default", ["0.50", "1.00", "2.00"]), ("fog", "day", ["8", "10", "40"])]
        {
            for ((w, h), median) in SEED_SIZES.iter().zip(medians) {
                saved.push_str(&format!(
                    "=== {chapter} {view} {w}x{h}\n{chapter} on Some GPU (Vulkan, DiscreteGpu), {w}x{h}, 10 frames per view\n\
                     | view | what | min ms | median ms | p95 ms |\n|---|---|---:|---:|---:|\n\
                     | other | frame (CPU+GPU) | 9.00 | 9.00 | 9.00 |\n\
                     | {view} | frame (CPU+GPU) | 0.10 | {median} | 99.00 |\n\
                     | {view} | GPU: scene pass | 0.01 | 0.02 | 0.03 |\n\n- {view}: setup (`Chapter::new`) 10 ms\n"
                ));
                if counted && chapter == "fog" {
                    let scene = if *w == 1920 { "1,234,567" } else { "7" };
                    saved.push_str(&format!(
                        "\nTriangles drawn in a frame, pass by pass, counted from the draws recorded:\n\n\
                         | view | pass | draws | triangles |\n|---|---|---:|---:|\n\
                         | {view} | scene | 12 | {scene} |\n| {view} | tone map | 1 | 1 |\n\n\
                         Each view's median frame against `x`'s:\n\n| view | median frame ms | × `x` |\n\
                         |---|---:|---:|\n| {view} | 2.00 | 1.00 |\n"
                    ));
                }
            }
        }
        saved
    }

    #[test]
    fn the_sizes_table_has_each_medians_frames_per_second() {
        let runs = parse_size_runs(&sample(), Path::new("sample.txt")).unwrap();
        assert_eq!(runs.len(), 6);
        let (adapter, table) = sizes_table(&runs).unwrap();
        assert_eq!(adapter, "Some GPU (Vulkan, DiscreteGpu)");
        let lines: Vec<&str> = table.lines().collect();
        assert_eq!(lines[0], "| chapter | 1280 × 720 | 1920 × 1080 | 2560 × 1440 | triangles at 1920 × 1080 | frame |");
        assert_eq!(lines[1], "|---|---:|---:|---:|---:|---:|");
        // Runs from before the bench fingerprinted frames: no frame.
        assert_eq!(
            lines[2],
            "| triangle (`default`) | 0.50 ms, 2000.0 FPS | 1.00 ms, 1000.0 FPS | 2.00 ms, 500.0 FPS | — | — |"
        );
        assert_eq!(lines[3], "| fog (`day`) | 8 ms, 125.0 FPS | 10 ms, 100.0 FPS | 40 ms, 25.0 FPS | — | — |");
        // A run that printed its frames gives its view's.
        let framed = sample().replacen(
            "=== fog day 1920x1080",
            &format!(
                "\n{}:\n\n| view | frame | samples | passes |\n|---|---|---:|---|\n| day | 0a1b2c3d | 4 | x |\n\
                 === fog day 1920x1080",
                crate::figures::FRAMES_HEADING
            ),
            1,
        );
        let (_, table) = sizes_table(&parse_size_runs(&framed, Path::new("sample.txt")).unwrap()).unwrap();
        assert!(table.lines().nth(3).unwrap().ends_with("| — | 0a1b2c3d |"), "{table}");
        assert_eq!(lines.len(), 4);
    }

    /// The last column adds up the passes of the run at 1920 × 1080 (the
    /// sample's 1,234,567 + 1, worked by hand), not another size's, and
    /// reads no row of the tables around it.
    #[test]
    fn the_sizes_table_gives_the_triangles_at_the_budget_size() {
        let runs = parse_size_runs(&sample_with_triangles(true), Path::new("sample.txt")).unwrap();
        let (_, table) = sizes_table(&runs).unwrap();
        let lines: Vec<&str> = table.lines().collect();
        assert!(lines[2].ends_with("| — | — |"), "the triangle chapter counted nothing: {}", lines[2]);
        assert_eq!(lines[3], "| fog (`day`) | 8 ms, 125.0 FPS | 10 ms, 100.0 FPS | 40 ms, 25.0 FPS | 1,234,568 | — |");
        let broken = sample_with_triangles(true).replace("| 1,234,567 |", "| many |");
        let runs = parse_size_runs(&broken, Path::new("sample.txt")).unwrap();
        let error = format!("{:#}", sizes_table(&runs).err().unwrap());
        assert!(error.contains("fog --view day --size 1920x1080") && error.contains("`many`"), "{error}");
        assert_eq!(
            (thousands(0), thousands(999), thousands(1000), thousands(12345678)),
            ("0".into(), "999".into(), "1,000".into(), "12,345,678".into())
        );
    }

    #[test]
    fn a_failed_or_missing_run_is_an_error_that_names_it() {
        // The run at 1920x1080 printed only an error.
        let failed = sample().replacen("| default | frame (CPU+GPU) | 0.10 | 1.00 |", "| x |", 1);
        let runs = parse_size_runs(&failed, Path::new("sample.txt")).unwrap();
        let error = format!("{:#}", sizes_table(&runs).err().unwrap());
        assert!(
            error.contains("triangle --view default --size 1920x1080") && error.contains("did the run fail"),
            "{error}"
        );

        let mixed = sample().replacen("fog on Some GPU", "fog on Other GPU", 1);
        let runs = parse_size_runs(&mixed, Path::new("sample.txt")).unwrap();
        let error = format!("{:#}", sizes_table(&runs).err().unwrap());
        assert!(error.contains("fog --view day --size 1280x720 ran on Other GPU"), "{error}");

        let runs = parse_size_runs(&sample(), Path::new("sample.txt")).unwrap();
        let error = format!("{:#}", sizes_table(&runs[1..]).err().unwrap());
        assert!(error.contains("no run of triangle at 1280x720"), "{error}");

        let error = format!("{:#}", parse_size_runs("=== triangle 1280x720\n", Path::new("s.txt")).err().unwrap());
        assert!(error.contains("s.txt:1") && error.contains("=== CHAPTER VIEW WxH"), "{error}");
    }

    #[test]
    fn a_chapter_page_keeps_the_tables_and_drops_the_time_lines() {
        let saved = "fog on Some GPU (Vulkan, DiscreteGpu), 1280x720, 10 frames per view\n\
                     | view | what | min ms | median ms | p95 ms |\n|---|---|---:|---:|---:|\n\
                     | day | frame (CPU+GPU) | 1.00 | 2.00 | 3.00 |\n\n- day: setup (`Chapter::new`) 10 ms\n\n\
                     real\t0m0.273s\nuser\t0m0.038s\nsys\t0m0.195s\n";
        let (first, tables) = chapter_tables("fog", saved, Path::new("fog.txt")).unwrap();
        assert_eq!(first, "fog on Some GPU (Vulkan, DiscreteGpu), 1280x720, 10 frames per view");
        assert_eq!(
            tables,
            "| view | what | min ms | median ms | p95 ms |\n|---|---|---:|---:|---:|\n\
             | day | frame (CPU+GPU) | 1.00 | 2.00 | 3.00 |\n\n- day: setup (`Chapter::new`) 10 ms\n"
        );
        let error = format!("{:#}", chapter_tables("water", saved, Path::new("water.txt")).err().unwrap());
        assert!(error.contains("water.txt") && error.contains("`water on ADAPTER"), "{error}");
    }

    #[test]
    fn a_gh100_is_named_for_what_it_is_and_a_graphics_card_is_not_qualified() {
        let about = what_the_gpu_is("GPU 0: NVIDIA H200 (UUID: GPU-1)\n16\n").unwrap();
        assert!(about.starts_with("The NVIDIA H200 is NVIDIA's GH100 chip") && about.contains("only two"), "{about}");
        assert!(what_the_gpu_is("GPU 0: NVIDIA H100 80GB HBM3 (UUID: GPU-2)\n").is_some());
        assert_eq!(what_the_gpu_is("GPU 0: NVIDIA GeForce RTX 4090 (UUID: GPU-3)\n"), None);
        assert_eq!(what_the_gpu_is("16\nmodel name\t: Some CPU\n"), None);
    }

    #[test]
    fn the_cpu_comes_from_the_saved_machine_file() {
        let gpu_txt = "GPU 0: Some GPU (UUID: GPU-1)\n16\nmodel name\t: Some CPU\n";
        assert_eq!(saved_cpu(gpu_txt, Path::new("gpu.txt")).unwrap(), "Some CPU, 16 threads");
        assert!(saved_cpu("GPU 0: Some GPU\n", Path::new("gpu.txt")).is_err());
    }
}
