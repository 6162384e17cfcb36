//! The flags every chapter binary accepts, parsed and checked: a bad value
//! is a one-line error naming the flag and what it accepts.

use std::path::{Path, PathBuf};

use clap::{CommandFactory, FromArgMatches, Parser};

use crate::{Antialiasing, CameraPlace, Chapter, Gpu};

/// Width and height in pixels.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Size {
    pub width: u32,
    pub height: u32,
}

fn parse_size(text: &str) -> Result<Size, String> {
    let expected = "expected WIDTHxHEIGHT, both at least 1, like 1280x720";
    let (w, h) = text.split_once(['x', 'X']).ok_or(expected)?;
    match (w.trim().parse::<u32>(), h.trim().parse::<u32>()) {
        (Ok(width), Ok(height)) if width > 0 && height > 0 => Ok(Size { width, height }),
        _ => Err(expected.into()),
    }
}

fn parse_time(text: &str) -> Result<f32, String> {
    match text.parse::<f32>() {
        Ok(t) if t.is_finite() => Ok(t),
        _ => Err("expected a finite number of seconds, like 12.5".into()),
    }
}

fn parse_camera(text: &str) -> Result<CameraPlace, String> {
    text.parse()
}

/// `--antialiasing`'s values for a chapter with or without a post chain,
/// so that `post` in a chapter without one is an error listing the others.
fn antialiasing_parser(post_chain: bool) -> impl clap::builder::TypedValueParser<Value = Antialiasing> {
    use clap::ValueEnum as _;
    use clap::builder::TypedValueParser as _;
    let offered: Vec<_> = Antialiasing::offered(post_chain).filter_map(|a| a.to_possible_value()).collect();
    clap::builder::PossibleValuesParser::new(offered)
        .map(|name| Antialiasing::from_str(&name, true).expect("a name the parser offered"))
}

/// Flags shared by every chapter (`--help` prints them).
#[derive(Parser, Debug, Clone)]
pub struct Args {
    /// Render one picture offscreen (no window or display needed) and write it to PATH, a .png file.
    #[arg(long, value_name = "PATH")]
    pub screenshot: Option<PathBuf>,

    /// Picture size for --screenshot and --bench, or the window's first size.
    #[arg(long, value_name = "WxH", value_parser = parse_size, default_value = "1280x720")]
    pub size: Size,

    /// Scene time in seconds. Headless pictures default to the chapter's snapshot time; the window starts at 0.
    #[arg(long, value_name = "SECONDS", value_parser = parse_time, allow_negative_numbers = true)]
    pub time: Option<f32>,

    /// How edges are smoothed: off, msaa (4 samples a pixel where the adapter can), and in chapters
    /// 08 to 11 post (FXAA over the finished picture) or both.
    #[arg(long, value_enum, value_name = "HOW", default_value = "msaa")]
    pub antialiasing: Antialiasing,

    /// The view to show (--list-views lists them with what each shows).
    #[arg(long, value_name = "NAME")]
    pub view: Option<String>,

    /// Look from this place: the position in metres, then yaw and pitch in degrees, as the overlay's
    /// camera line shows them (its copy button copies this flag). Applied after --view, so it
    /// replaces a preset's camera; in the window, headless and in --bench alike.
    #[arg(long, value_name = "X,Y,Z,YAW,PITCH", value_parser = parse_camera, allow_hyphen_values = true)]
    pub camera: Option<CameraPlace>,

    /// Print the chapter's views and exit.
    #[arg(long)]
    pub list_views: bool,

    /// With --bench: frames to measure (default: the chapter's, usually 100). With a window: close after N frames.
    #[arg(long, value_name = "N", value_parser = clap::value_parser!(u32).range(1..=1_000_000))]
    pub frames: Option<u32>,

    /// Render frames offscreen and print min/median/p95 frame times (every view unless --view is given).
    #[arg(long)]
    pub bench: bool,

    /// Open the window with the shader panel on FILE, a WGSL file under shaders/ that the chapter
    /// builds from (the panel lists them), like triangle/triangle.wgsl; with no FILE, on the chapter's
    /// main file.
    #[arg(long, value_name = "FILE", num_args = 0..=1, default_missing_value = "", conflicts_with_all = ["screenshot", "bench"])]
    pub edit: Option<String>,

    /// Where the shader panel puts the cursor: the first place this text occurs in the `edit` file
    /// (a page's `at=`, for the book's "try it" links).
    #[arg(skip)]
    pub edit_at: Option<String>,

    /// For tests that drive the window: after every frame, write the runner's state (frame count,
    /// surface size, camera) as one line to PATH.
    #[arg(long, value_name = "PATH", hide = true)]
    pub probe: Option<PathBuf>,

    /// The chapter's own flags (`Chapter::FLAGS`), as given.
    #[arg(skip)]
    pub chapter_flags: crate::chapter::FlagValues,
}

impl Args {
    /// Parses the command line for chapter `C`; the view names become the
    /// allowed values of `--view`, so a typo lists the real ones.
    pub fn parse_for<C: Chapter>() -> Result<Self, clap::Error> {
        Self::parse_from_for::<C>(std::env::args_os())
    }

    pub fn parse_from_for<C: Chapter>(
        args: impl IntoIterator<Item = impl Into<std::ffi::OsString> + Clone>,
    ) -> Result<Self, clap::Error> {
        Self::parse_from_of(&crate::chapter::About::of::<C>(), args)
    }

    /// [`Args::parse_from_for`], whatever the chapter's type.
    pub fn parse_from_of(
        about: &crate::chapter::About,
        args: impl IntoIterator<Item = impl Into<std::ffi::OsString> + Clone>,
    ) -> Result<Self, clap::Error> {
        let names: Vec<&'static str> = about.views.iter().map(|v| v.name).collect();
        let mut command = Self::command()
            .name(about.name)
            .about(format!("{}: opens a window; with --screenshot or --bench, renders headless.", about.title))
            .mut_arg("view", |arg| arg.value_parser(clap::builder::PossibleValuesParser::new(names)))
            .mut_arg("antialiasing", |arg| arg.value_parser(antialiasing_parser(about.post_antialiasing)));
        for flag in about.flags {
            let arg = clap::Arg::new(flag.name).long(flag.name).help(flag.help);
            command = command.arg(if flag.is_switch() {
                arg.action(clap::ArgAction::SetTrue)
            } else {
                arg.value_name(flag.value_name)
            });
        }
        let matches = command.try_get_matches_from(args)?;
        let mut parsed = Self::from_arg_matches(&matches)?;
        for flag in about.flags {
            if flag.is_switch() {
                if matches.get_flag(flag.name) {
                    parsed.chapter_flags.0.push((flag.name, "true".into()));
                }
            } else if let Some(value) = matches.get_one::<String>(flag.name) {
                parsed.chapter_flags.0.push((flag.name, value.clone()));
            }
        }
        Ok(parsed)
    }

    /// Index of the chosen view (0 when none was given).
    pub fn view_index<C: Chapter>(&self) -> usize {
        self.view_index_in(C::VIEWS)
    }

    /// [`Args::view_index`] among `views`.
    pub fn view_index_in(&self, views: &[crate::View]) -> usize {
        self.view.as_deref().and_then(|name| views.iter().position(|v| v.name == name)).unwrap_or(0)
    }
}

/// A mistake in the flags found after parsing (exit code 2): written in
/// `chapter`, whose own flags can be mistaken too, and named here, where
/// runners look for it.
pub use crate::chapter::UsageError;

/// Fails early, before any GPU work, if `path` cannot be written. A file
/// made to find out is removed again: the picture is written only once it
/// exists, and a run that fails on the way leaves nothing behind (an
/// existing file is opened without changing it).
pub fn check_writable(path: &Path) -> anyhow::Result<()> {
    if path.extension().is_none_or(|e| !e.eq_ignore_ascii_case("png")) {
        return Err(UsageError(format!("--screenshot {}: the file name must end in .png", path.display())).into());
    }
    let existed = path.exists();
    std::fs::OpenOptions::new()
        .create(true)
        .truncate(false)
        .write(true)
        .open(path)
        .map_err(|e| UsageError(format!("--screenshot {}: cannot write there: {e}", path.display())))?;
    if !existed {
        let _ = std::fs::remove_file(path);
    }
    Ok(())
}

/// The device's largest texture side; a bigger `--size` is refused.
pub fn check_size(gpu: &Gpu, size: Size) -> Result<(), UsageError> {
    let max = gpu.device.limits().max_texture_dimension_2d;
    if size.width > max || size.height > max {
        return Err(UsageError(format!(
            "--size {}x{} is larger than {} allows: at most {max} pixels per side",
            size.width,
            size.height,
            gpu.adapter.get_info().name
        )));
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sizes() {
        assert_eq!(parse_size("640x360"), Ok(Size { width: 640, height: 360 }));
        assert_eq!(parse_size("7X3"), Ok(Size { width: 7, height: 3 }));
        for bad in ["0x0", "640", "x360", "-5x3", "axb", "640x0"] {
            assert!(parse_size(bad).is_err(), "{bad} accepted");
        }
    }

    #[test]
    fn times() {
        assert_eq!(parse_time("12.5"), Ok(12.5));
        assert_eq!(parse_time("-1"), Ok(-1.0));
        for bad in ["NaN", "inf", "-inf", "soon", ""] {
            assert!(parse_time(bad).is_err(), "{bad} accepted");
        }
    }

    #[test]
    fn unwritable_screenshot_paths_are_usage_errors() {
        let error = check_writable(Path::new("/no/such/dir/out.png")).unwrap_err();
        assert!(error.is::<UsageError>());
        assert!(error.to_string().starts_with("--screenshot /no/such/dir/out.png: cannot write there"), "{error}");
        let error = check_writable(Path::new("out.jpg")).unwrap_err();
        assert!(error.to_string().contains("must end in .png"), "{error}");
    }

    #[test]
    fn checking_a_screenshot_path_leaves_no_file_behind() {
        let path = std::env::temp_dir().join(format!("check-writable-{}.png", std::process::id()));
        let _ = std::fs::remove_file(&path);
        check_writable(&path).unwrap();
        assert!(!path.exists(), "no empty file where none was");
        std::fs::write(&path, b"an older picture").unwrap();
        check_writable(&path).unwrap();
        assert_eq!(std::fs::read(&path).unwrap(), b"an older picture", "an existing file is kept as it is");
        std::fs::remove_file(&path).unwrap();
    }
}
