//! Every view of every chapter against its reference image.

use std::collections::BTreeSet;
use std::path::Path;

#[test]
fn triangle() {
    snapshots::assert_chapter("triangle");
}

#[test]
fn camera() {
    snapshots::assert_chapter("camera");
}

#[test]
fn terrain() {
    snapshots::assert_chapter("terrain");
}

#[test]
fn fog() {
    snapshots::assert_chapter("fog");
}

#[test]
fn instancing() {
    snapshots::assert_chapter("instancing");
}

#[test]
fn skybox() {
    snapshots::assert_chapter("skybox");
}

#[test]
fn water() {
    snapshots::assert_chapter("water");
}

/// A chapter crate missing from the registry would never be snapshot-tested.
#[test]
fn every_chapter_crate_is_registered() {
    let chapters = Path::new(env!("CARGO_MANIFEST_DIR")).join("../chapters");
    let mut on_disk = BTreeSet::new();
    for dir in std::fs::read_dir(&chapters).unwrap() {
        let manifest = std::fs::read_to_string(dir.unwrap().path().join("Cargo.toml")).unwrap();
        let name = manifest.lines().find_map(|l| l.strip_prefix("name = ")).expect("package name");
        on_disk.insert(name.trim_matches('"').to_string());
    }
    let registered: BTreeSet<String> = snapshots::chapters().iter().map(|e| e.name.to_string()).collect();
    assert_eq!(on_disk, registered);
}

/// A reference for a view that no longer exists is a figure nobody checks.
#[test]
fn no_stale_references() {
    for dir in std::fs::read_dir(snapshots::snapshot_dir()).unwrap() {
        let dir = dir.unwrap().path();
        let chapter = dir.file_name().unwrap().to_string_lossy().to_string();
        let entry = snapshots::find(&chapter).unwrap_or_else(|| panic!("{} belongs to no chapter", dir.display()));
        for file in std::fs::read_dir(&dir).unwrap() {
            let path = file.unwrap().path();
            let stem = path.file_stem().unwrap().to_string_lossy().to_string();
            if stem.ends_with("-actual") || stem.ends_with("-diff") {
                continue; // left by a failing run, ignored by git
            }
            assert!(entry.views.iter().any(|v| v.name == stem), "{} is not a view of {chapter}", path.display());
        }
    }
}

/// Scene time and seeds are inputs: the same request gives the same bytes.
#[test]
fn renders_are_deterministic() {
    for entry in snapshots::chapters() {
        let (first, second) = (entry.render_view(0).unwrap(), entry.render_view(0).unwrap());
        assert!(first == second, "{}: two renders of the same view differ", entry.name);
    }
}
