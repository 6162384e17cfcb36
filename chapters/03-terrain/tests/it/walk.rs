//! `--walk`, a flag without a value, reaches the chapter: the terrain
//! chapters start on foot with it, and its misuse is a usage error.

use common::args::Args;
use terrain::TerrainChapter;
use terrain::ground::{Movement, movement_from_flags};

#[test]
fn the_walk_switch_takes_no_value() {
    let walking = Args::parse_from_for::<TerrainChapter>(["terrain", "--walk"]).unwrap();
    assert_eq!(movement_from_flags(&walking.chapter_flags), Movement::Walk);
    let flying = Args::parse_from_for::<TerrainChapter>(["terrain"]).unwrap();
    assert_eq!(movement_from_flags(&flying.chapter_flags), Movement::Fly);
    let error = Args::parse_from_for::<TerrainChapter>(["terrain", "--walk=yes"]).unwrap_err();
    assert!(error.to_string().contains("--walk"), "{error}");
    let help = Args::parse_from_for::<TerrainChapter>(["terrain", "--help"]).unwrap_err().to_string();
    assert!(help.contains("--walk") && help.contains("G switches"), "{help}");
}
