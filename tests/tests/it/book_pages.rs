//! The book's shape (`snapshots::book`): its readers of pages, checked
//! on small pages written here, then the whole book checked, as
//! `cargo xtask book` checks it before building.

use course::SubPage;
use snapshots::book::*;

/// The book as it is: every problem with its shape, at once.
#[test]
fn the_book_is_made_of_lessons_in_book_order() {
    let src = book_src();
    let summary = std::fs::read_to_string(src.join("SUMMARY.md")).unwrap();
    let problems = check(&src, &snapshots::chapters(), &summary).unwrap();
    assert!(problems.is_empty(), "the book's pages:\n  {}", problems.join("\n  "));
}

#[test]
fn prose_leaves_out_code_tables_markup_and_directives() {
    let page = "# Title\n\nOne two three.\n\n```rust\nlet a = 1;\nlet b = 2;\n```\n\n| a | b |\n|---|---|\n\
                | c | d |\n\n![a picture of words](x.png)\n\n<details><summary>Solution</summary>\n\n\
                Four [five](https://example.com/a-b-c) {{#figure [x | y]}} ms {{#check 1 < 2}}{{#run fog default}}\n";
    // Title, One two three, Solution, Four five (figure) ms.
    assert_eq!(prose_words(page), 1 + 3 + 1 + 4);
}

#[test]
fn heading_ids_are_mdbooks() {
    assert_eq!(heading_id("Culling rock by rock, on the GPU"), "culling-rock-by-rock-on-the-gpu");
    assert_eq!(heading_id("`draw_indexed` and [links](x.md)"), "draw_indexed-and-links");
    assert_eq!(heading_id("Custom {#mine}"), "mine");
    let ids = heading_ids("# A\n## Numbers\n### Numbers\n```\n# not a heading\n```\n");
    assert_eq!(ids, ["a", "numbers", "numbers-1"].iter().map(|s| s.to_string()).collect());
}

#[test]
fn exercises_are_counted_and_named() {
    let page = "# A\n\n## Exercises\n\n1. First.\n\n   1. not an exercise\n\n2. Second.\n\n## Questions\n\n1. Q\n";
    assert_eq!(exercise_count(page), 2);
    assert_eq!(exercises_named("see exercise 3, and exercises 1 and 2, exercises 4–5"), vec![3, 1, 2, 4, 5]);
    assert_eq!(exercises_named("the exercises in chapter 2"), Vec::<u32>::new());
}

#[test]
fn an_opening_page_lists_its_lessons_and_reference_pages() {
    let opening = "# 05 · Instancing\n\n## The lessons\n\n1. [One draw](one-draw.md): rocks.\n   \
                   [not an item](x.md)\n2. [The GPU culls (advanced)](gpu.md)\n\n## Reference pages\n\n\
                   - [Numbers](numbers.md)\n";
    let lessons = listed_pages(opening, "05-instancing", LESSONS_HEADING);
    assert_eq!(
        lessons,
        vec![
            SubPage { title: "One draw".into(), file: "05-instancing/one-draw.md".into() },
            SubPage { title: "The GPU culls (advanced)".into(), file: "05-instancing/gpu.md".into() },
        ]
    );
    let reference = listed_pages(opening, "05-instancing", REFERENCE_HEADING);
    assert_eq!(reference, vec![SubPage { title: "Numbers".into(), file: "05-instancing/numbers.md".into() }]);
}

#[test]
fn links_resolve_against_the_page_folder() {
    assert_eq!(page_target("05-instancing/a.md", "b.md#x"), Some(("05-instancing/b.md".into(), Some("x".into()))));
    assert_eq!(page_target("05-instancing/a.md", "../frame-rates.md"), Some(("frame-rates.md".into(), None)));
    assert_eq!(page_target("05-instancing/a.md", "#here"), Some(("05-instancing/a.md".into(), Some("here".into()))));
    assert_eq!(page_target("05-instancing/a.md", "../figures/x.png"), None);
    assert_eq!(page_target("a.md", "https://wgpu.rs"), None);
    assert_eq!(page_target("a.md", "../../x.md"), None);
}

/// Page 05's old sentences, as the fact-check found them: every typed
/// measurement is named; sizes, figures and quotations are not.
#[test]
fn typed_measurements_are_found_and_figures_are_not() {
    let old_page_05 = "costs three times as much at 10,000 rocks: 58 ms against 19 ms, and \
                       19, 144 and 1287 ms for 10k, 100k and 1M rocks; a flat floor of 1216 ms; \
                       32.68 ms at 1920 × 1080, about 1 ms for 790 calls, 29% and 2.5×, 4 s in all.";
    let found: Vec<String> = typed_measurements(old_page_05).into_iter().map(|(_, t)| t).collect();
    assert_eq!(found, ["58 ms", "19 ms", "1287 ms", "1216 ms", "32.68 ms", "1 ms", "29%", "2.5×", "4 s"]);
    let clean = "a 3×3 filter at 1280 × 720, {{#figure [x | y]}} ms, `16 ms` in code, \
                 {{#cited 66 FPS | seed 001}}, chapter 05's 4 samples, 2 m away, the 1960s, x2 times.\n\
                 | 12 ms | in a table |\n```\n9 ms in code\n```\n";
    assert_eq!(typed_measurements(clean), Vec::<(usize, String)>::new());
}

/// Names in code font resolve against the workspace, as the book's check
/// reads them; a misspelt one does not, and a plain word is not a name.
#[test]
fn code_named_in_prose_resolves_against_the_workspace() {
    let index = CodeIndex::build(&book_src().join("../..")).unwrap();
    for name in ["FogSettings", "terrain::TerrainRenderer", "opaque_distance()", "MAX_FAR", "fog.wgsl", "fog/fog.wgsl"]
    {
        assert_eq!(index.resolves(name), Some(true), "{name}");
    }
    // Spelt in pieces: this file is in the index, and a whole misspelt
    // word here would be found in it.
    for pieces in [["Fog", "Setings"], ["opaque_", "distanse()"], ["MAX_", "FARR"], ["fogg", ".wgsl"]] {
        let name = pieces.concat();
        assert_eq!(index.resolves(&name), Some(false), "{name}");
    }
    for name in ["--view", "density", "a + b", "1280x720", "vec4<f32>"] {
        assert_eq!(index.resolves(name), None, "{name}");
    }
    let spans = code_spans("the `dense` view, {{#view fog dense}}, and `x`\n```\n`not prose`\n```\n");
    assert_eq!(spans, [(1, "dense".to_string()), (1, "x".to_string())]);
}
