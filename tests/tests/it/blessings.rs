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
    assert_eq!(log.blessing_of("fedcba9876543210").map(|e| e.view.as_str()), Some("lighting/dusk"));
    assert!(log.blessing_of("0123456789abcdef").is_none(), "an old hash blesses nothing");
    let broken = format!("{HEADING}| lighting/day | - | abc |\n");
    assert!(Log::parse(&broken).unwrap_err().contains("3 cells"));
}

#[test]
fn the_hash_is_sha256s_first_sixteen_digits() {
    // `printf abc | sha256sum`: ba7816bf8f01cfea414140de5dae2223…
    assert_eq!(hash(b"abc"), "ba7816bf8f01cfea");
}
