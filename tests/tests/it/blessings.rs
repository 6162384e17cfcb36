//! The bless log's lines read back as written, and a picture's name is
//! the SHA-256 of its bytes.

use snapshots::blessings::{Entry, HEADING, Log, hash};

#[test]
fn an_entry_reads_back_as_written_pipes_and_all() {
    let entry = Entry {
        view: "lighting/day".into(),
        old: Some("0123456789abcdef".into()),
        new: "fedcba9876543210".into(),
        mean: Some(0.00123),
        patch: Some(0.045),
        adapter: "llvmpipe · Vulkan".into(),
        reason: "brighter sun | and a mast".into(),
    };
    let new_view = Entry { view: "lighting/dusk".into(), old: None, mean: None, patch: None, ..entry.clone() };
    let text = format!("{HEADING}{entry}\n{new_view}\n");
    let log = Log::parse(&text).unwrap();
    assert_eq!(log.entries, [entry, new_view]);
    assert_eq!(log.blessing_of("lighting/dusk", "fedcba9876543210").map(|e| e.view.as_str()), Some("lighting/dusk"));
    assert!(log.blessing_of("lighting/day", "0123456789abcdef").is_none(), "an old hash blesses nothing");
    // The same bytes blessed for one view bless no other: `flat.png`
    // copied over `default.png` is found out.
    assert!(log.blessing_of("lighting/day", "fedcba9876543210").is_some());
    assert!(log.blessing_of("lighting/night", "fedcba9876543210").is_none());
    let broken = format!("{HEADING}| lighting/day | - | abc |\n");
    assert!(Log::parse(&broken).unwrap_err().contains("3 cells"));
}

#[test]
fn the_hash_is_sha256s_first_sixteen_digits() {
    // `printf abc | sha256sum`: ba7816bf8f01cfea414140de5dae2223…
    assert_eq!(hash(b"abc"), "ba7816bf8f01cfea");
}

/// A reference is compared exactly (within a colour level) only where the
/// log says it was made on this adapter and for this view; anywhere else
/// by FLIP.
#[test]
fn a_reference_is_exact_only_on_its_own_adapter_and_for_its_own_view() {
    use snapshots::snapshot::{Rule, Tolerance};
    let folder = std::env::temp_dir().join(format!("rules-{}", std::process::id()));
    std::fs::create_dir_all(&folder).unwrap();
    let reference = folder.join("day.png");
    std::fs::write(&reference, b"picture bytes").unwrap();
    let entry = Entry {
        view: "lighting/day".into(),
        old: None,
        new: hash(b"picture bytes"),
        mean: None,
        patch: None,
        adapter: "llvmpipe (LLVM 15.0.6, 256 bits) · Vulkan · Mesa 22.3.6".into(),
        reason: "a test".into(),
    };
    let log = || Log::parse(&format!("{HEADING}{entry}\n")).unwrap();
    let here = snapshots::Rules::from_parts(log(), entry.adapter.clone());
    assert_eq!(here.for_reference("lighting/day", &reference, Tolerance::DEFAULT), Rule::Exact);
    let copied = here.for_reference("lighting/night", &reference, Tolerance::DEFAULT);
    assert_eq!(copied, Rule::Perceptual(Tolerance::DEFAULT), "another view's picture is no blessing of this one");
    let elsewhere = snapshots::Rules::from_parts(log(), "NVIDIA H200 · Vulkan · 570.0".into());
    assert_eq!(
        elsewhere.for_reference("lighting/day", &reference, Tolerance::DEFAULT),
        Rule::Perceptual(Tolerance::DEFAULT)
    );
    std::fs::remove_dir_all(&folder).unwrap();
}
