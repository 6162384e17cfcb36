//! Every shader, translated for the backends a learner may run on but this
//! machine does not: Metal's MSL (a Mac), Direct3D 12's HLSL (Windows) and,
//! for the chapters that draw on WebGL2, GLSL ES 3.00. Here wgpu only ever
//! translates to SPIR-V (lavapipe) and desktop GLSL (llvmpipe), so a WGSL
//! construct another back end cannot write would first fail on a learner's
//! machine. Each file is composed as the chapters compose it (naga_oil,
//! with and without `CLIP_DISTANCES` where it asks), with the workspace's
//! own naga.

use std::collections::BTreeMap;
use std::path::Path;

use naga::back::{glsl, hlsl, msl};
use naga::valid::{Capabilities, ModuleInfo, ValidationFlags, Validator};

use crate::shader_files::import_graph;

/// The one define the shaders test: set when the device has clip distances.
const CLIP_DISTANCES: &str = "CLIP_DISTANCES";

/// A composed shader: the file, the defines it was composed with, naga's
/// module and what validation learned of it.
struct Composed {
    file: String,
    defs: Vec<&'static str>,
    module: naga::Module,
    info: ModuleInfo,
}

impl Composed {
    fn name(&self) -> String {
        if self.defs.is_empty() { self.file.clone() } else { format!("{} with {}", self.file, self.defs.join(", ")) }
    }
}

fn shaders_dir() -> std::path::PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../shaders")
}

/// `file`'s imports, each after its own, as (path, text).
fn imports_in_order(file: &str, graph: &BTreeMap<String, Vec<String>>) -> Vec<(String, String)> {
    fn visit(file: &str, graph: &BTreeMap<String, Vec<String>>, done: &mut Vec<String>) {
        for import in &graph[file] {
            if !done.contains(import) {
                visit(import, graph, done);
                done.push(import.clone());
            }
        }
    }
    let mut order = Vec::new();
    visit(file, graph, &mut order);
    order.into_iter().map(|path| (path.clone(), std::fs::read_to_string(shaders_dir().join(&path)).unwrap())).collect()
}

/// Every file with an entry point, composed with each set of defines it
/// reacts to. Composing errors are collected in `failures`.
fn every_shader(failures: &mut Vec<String>) -> Vec<Composed> {
    let graph = import_graph(&shaders_dir());
    let mut composed = Vec::new();
    for file in graph.keys() {
        let text = std::fs::read_to_string(shaders_dir().join(file)).unwrap();
        if !["@vertex", "@fragment", "@compute"].iter().any(|stage| text.contains(stage)) {
            continue;
        }
        let imports = imports_in_order(file, &graph);
        let asks = |t: &str| t.contains(&format!("#ifdef {CLIP_DISTANCES}"));
        let def_sets: Vec<Vec<&'static str>> = if asks(&text) || imports.iter().any(|(_, t)| asks(t)) {
            vec![vec![], vec![CLIP_DISTANCES]]
        } else {
            vec![vec![]]
        };
        let import_refs: Vec<(&str, String)> = imports.iter().map(|(p, t)| (p.as_str(), t.clone())).collect();
        for defs in def_sets {
            let module = match common::shader::compose_with(&text, file, &import_refs, &defs) {
                Ok(module) => module,
                Err(error) => {
                    failures.push(format!("{file} {defs:?} does not compose: {error}"));
                    continue;
                }
            };
            // As the chapters' device would: clip distances where asked.
            let capabilities = if defs.is_empty() { Capabilities::empty() } else { Capabilities::CLIP_DISTANCES };
            match Validator::new(ValidationFlags::all(), capabilities).validate(&module) {
                Ok(info) => composed.push(Composed { file: file.clone(), defs, module, info }),
                Err(error) => failures.push(format!("{file} {defs:?} is not valid: {}", error.emit_to_string(&text))),
            }
        }
    }
    composed
}

/// Metal Shading Language 2.1, what wgpu's Metal back end writes on macOS
/// 10.14 (it picks the language version by the system's; older systems
/// get older versions, where the rocks' `instance_index` and the split-sum
/// table's `reverseBits` have no MSL 1.0 spelling), with the bindings naga
/// makes up where a pipeline layout would give them.
fn to_msl(shader: &Composed) -> Result<(), String> {
    let options = msl::Options { lang_version: (2, 1), fake_missing_bindings: true, ..Default::default() };
    msl::write_string(&shader.module, &shader.info, &options, &msl::PipelineOptions::default())
        .map(drop)
        .map_err(|e| format!("{e:?}"))
}

/// HLSL for shader model 5.1, the least of the models wgpu's Direct3D 12
/// back end knows (it asks the device for the highest it has).
fn to_hlsl(shader: &Composed) -> Result<(), String> {
    let options =
        hlsl::Options { shader_model: hlsl::ShaderModel::V5_1, fake_missing_bindings: true, ..Default::default() };
    let mut out = String::new();
    hlsl::Writer::new(&mut out, &options, &hlsl::PipelineOptions::default())
        .write(&shader.module, &shader.info, None)
        .map(drop)
        .map_err(|e| format!("{e:?}"))
}

/// Entry points in the WebGL2 chapters' shaders that those chapters never
/// run on WebGL2, as (file, entry point, why). Each must still fail to
/// translate, or it has no business here.
const NOT_ON_WEBGL2: [(&str, &str, &str); 1] = [(
    "instancing/rocks.wgsl",
    "vs_culled",
    "reads the rocks the compute pass kept from a storage buffer; without compute shaders chapter 05 culls \
     chunks on the CPU and draws with vs_instanced (MarsPlain::pipelines makes vs_culled's pipelines only \
     with a layout for the culled list)",
)];

/// GLSL ES 3.00 as WebGL2 takes it, one entry point at a time (GLSL has
/// one `main` a program stage). Compute entry points are left out: WebGL2
/// has no compute stage, and the chapters that draw there do not use one;
/// so are [`NOT_ON_WEBGL2`]'s, which must fail.
fn to_glsl_es(shader: &Composed) -> Result<usize, String> {
    let options =
        glsl::Options { version: glsl::Version::Embedded { version: 300, is_webgl: true }, ..Default::default() };
    let mut written = 0;
    for entry in shader.module.entry_points.iter().filter(|e| e.stage != naga::ShaderStage::Compute) {
        let pipeline =
            glsl::PipelineOptions { shader_stage: entry.stage, entry_point: entry.name.clone(), multiview: None };
        let mut out = String::new();
        let written_out =
            glsl::Writer::new(&mut out, &shader.module, &shader.info, &options, &pipeline, Default::default())
                .and_then(|mut writer| writer.write());
        let excepted = NOT_ON_WEBGL2.iter().any(|(file, name, _)| *file == shader.file && *name == entry.name);
        match (written_out, excepted) {
            (Ok(_), false) => written += 1,
            (Err(_), true) => {}
            (Ok(_), true) => return Err(format!("{} now translates: take it out of NOT_ON_WEBGL2", entry.name)),
            (Err(e), false) => return Err(format!("{}: {e:?}", entry.name)),
        }
    }
    Ok(written)
}

/// The shader folders of the chapters that draw on WebGL2, and `common/`.
fn webgl2_folders() -> Vec<String> {
    let mut folders: Vec<String> =
        snapshots::chapters().iter().filter(|r| r.draws_on_webgl2()).map(|r| r.name.to_string()).collect();
    folders.push("common".into());
    folders
}

#[test]
fn every_shader_translates_to_msl_hlsl_and_for_webgl2_chapters_glsl_es() {
    let mut failures = Vec::new();
    let shaders = every_shader(&mut failures);
    let webgl2 = webgl2_folders();
    let mut glsl_entry_points = 0;
    for shader in &shaders {
        if let Err(error) = to_msl(shader) {
            failures.push(format!("{} to MSL: {error}", shader.name()));
        }
        if let Err(error) = to_hlsl(shader) {
            failures.push(format!("{} to HLSL: {error}", shader.name()));
        }
        // WebGL2 has no clip distances: those chapters run the fallback.
        let folder = shader.file.split('/').next().unwrap_or_default();
        if shader.defs.is_empty() && webgl2.iter().any(|f| f == folder) {
            match to_glsl_es(shader) {
                Ok(n) => glsl_entry_points += n,
                Err(error) => failures.push(format!("{} to GLSL ES 3.00: {error}", shader.name())),
            }
        }
    }
    assert!(failures.is_empty(), "{} failures:\n{}", failures.len(), failures.join("\n"));
    // A walk that found nothing would pass anything. When this was written,
    // `grep -rlE '@(vertex|fragment|compute)' shaders | wc -l` gave 33 files
    // with entry points, 4 of them composed twice (with CLIP_DISTANCES);
    // the WebGL2 chapters' folders held 27 vertex and fragment entry points
    // (`grep -cE '@(vertex|fragment)'` over triangle, camera, terrain, fog,
    // instancing, skybox and water), one of them in NOT_ON_WEBGL2.
    assert_eq!(shaders.len(), 37, "shaders composed: the walk changed, or shaders/ did (then update this)");
    assert_eq!(glsl_entry_points, 26, "entry points written as GLSL ES");
}
