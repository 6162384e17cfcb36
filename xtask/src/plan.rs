//! Which of `cargo xtask test`'s steps this system can run. Three need
//! tools that only Linux has, or that only Debian installs for us: the
//! OpenGL trials of the snapshot test (Mesa's EGL), the window test (Xvfb,
//! openbox, xdotool, xwd) and the browser test (Chromium). On a system
//! without them the test command runs everything else and ends with one
//! line per step it skipped, saying why; on Debian it installs them, or
//! names the one command to run when it may not.

/// What the test command found on this system.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct System {
    pub os: Os,
    /// `apt-get` can install what is missing (Debian or Ubuntu).
    pub debian: bool,
    pub has_egl: bool,
    pub has_window_tools: bool,
    pub has_chromium: bool,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Os {
    Linux,
    Mac,
    Windows,
    Other,
}

/// What to do about one optional step.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Decision {
    /// Its tools are there.
    Run,
    /// Install its Debian packages first (or name the command), then run.
    Install,
    /// Leave it out, for this reason.
    Skip(String),
}

/// The decisions for the three optional steps.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Plan {
    pub opengl: Decision,
    pub window: Decision,
    pub browser: Decision,
}

impl Plan {
    /// One line per skipped step, to print at the end of the run.
    pub fn skipped(&self) -> Vec<String> {
        [("OpenGL trials", &self.opengl), ("window test", &self.window), ("browser test", &self.browser)]
            .into_iter()
            .filter_map(|(step, decision)| match decision {
                Decision::Skip(why) => Some(format!("skipped the {step}: {why}")),
                _ => None,
            })
            .collect()
    }
}

/// What this system can run of the optional steps.
pub fn plan(system: System) -> Plan {
    let decide = |present: bool, linux_only: &str, what: &str| {
        if present {
            Decision::Run
        } else if system.os != Os::Linux {
            Decision::Skip(linux_only.to_string())
        } else if system.debian {
            Decision::Install
        } else {
            Decision::Skip(format!("{what} not found, and only Debian's packages are installed for you"))
        }
    };
    Plan {
        opengl: decide(
            system.has_egl,
            "they draw on Mesa's OpenGL through EGL, a Linux driver",
            "Mesa's EGL and OpenGL drivers (libEGL_mesa, swrast_dri) were",
        ),
        window: decide(
            system.has_window_tools,
            "it drives windows on a virtual X server (Xvfb), which is Linux's",
            "Xvfb, openbox, xdotool and xwd were",
        ),
        browser: decide(
            system.has_chromium,
            "set CHROMIUM to a Chromium or Chrome binary to run it here",
            "Chromium was (set CHROMIUM to a Chromium or Chrome binary)",
        ),
    }
}

/// This system, as the test command finds it.
pub fn this_system() -> System {
    let os = if cfg!(target_os = "linux") {
        Os::Linux
    } else if cfg!(target_os = "macos") {
        Os::Mac
    } else if cfg!(target_os = "windows") {
        Os::Windows
    } else {
        Os::Other
    };
    System {
        os,
        debian: std::path::Path::new("/etc/debian_version").exists(),
        has_egl: crate::prerequisites::opengl_present(),
        has_window_tools: crate::prerequisites::has_window_tools(),
        has_chromium: crate::web::chromium().is_some(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const DEBIAN_BARE: System =
        System { os: Os::Linux, debian: true, has_egl: false, has_window_tools: false, has_chromium: false };

    #[test]
    fn debian_installs_what_is_missing_and_skips_nothing() {
        let bare = plan(DEBIAN_BARE);
        assert_eq!(bare, Plan { opengl: Decision::Install, window: Decision::Install, browser: Decision::Install });
        assert!(bare.skipped().is_empty());
        let ready = System { has_egl: true, has_window_tools: true, has_chromium: true, ..DEBIAN_BARE };
        assert_eq!(plan(ready), Plan { opengl: Decision::Run, window: Decision::Run, browser: Decision::Run });
    }

    #[test]
    fn macos_and_windows_skip_the_linux_steps_and_say_why() {
        for os in [Os::Mac, Os::Windows] {
            let skipped = plan(System { os, debian: false, ..DEBIAN_BARE }).skipped();
            assert_eq!(skipped.len(), 3, "{skipped:?}");
            assert!(skipped[0].starts_with("skipped the OpenGL trials: ") && skipped[0].contains("EGL"));
            assert!(skipped[1].starts_with("skipped the window test: ") && skipped[1].contains("Xvfb"));
            assert!(skipped[2].starts_with("skipped the browser test: ") && skipped[2].contains("CHROMIUM"));
        }
    }

    #[test]
    fn a_browser_found_elsewhere_runs_the_browser_test_anywhere() {
        let mac = System { os: Os::Mac, debian: false, has_chromium: true, ..DEBIAN_BARE };
        assert_eq!(plan(mac).browser, Decision::Run);
    }

    #[test]
    fn another_linux_skips_only_what_it_lacks() {
        let fedora = System { debian: false, has_egl: true, ..DEBIAN_BARE };
        let fedora = plan(fedora);
        assert_eq!(fedora.opengl, Decision::Run);
        let skipped = fedora.skipped();
        assert_eq!(skipped.len(), 2, "{skipped:?}");
        assert!(skipped.iter().all(|line| line.contains("only Debian's packages are installed for you")));
    }
}
