//! What each chapter declares it needs of an adapter's limits, read
//! against two small adapters: WebGL2's guaranteed limits with a 2048-texel
//! side, and a WebGPU adapter's defaults.

use common::wgpu;

/// The chapters whose height maps are 4097 texels a side: 03 and every
/// chapter that draws its terrain.
const TERRAIN_CHAPTERS: [&str; 5] = ["terrain", "fog", "instancing", "skybox", "water"];

/// The chapters lit by chapter 08's lights, which need a WebGPU adapter.
const LIT_CHAPTERS: [&str; 4] = ["lighting", "textures", "shadows", "voronoi-water"];

#[test]
fn a_2048_texel_adapter_refuses_the_terrain_chapters_by_name() {
    let small = wgpu::Limits { max_texture_dimension_2d: 2048, ..wgpu::Limits::defaults() };
    for record in snapshots::chapters() {
        let missing = (record.needs)().missing_on(wgpu::Features::all(), wgpu::DownlevelFlags::all(), &small);
        let expected: &[&str] = if TERRAIN_CHAPTERS.contains(&record.name) {
            &["max_texture_dimension_2d of 4097 (it has 2048)"]
        } else if LIT_CHAPTERS.contains(&record.name) {
            // They ask for WebGPU's defaults in full.
            &["max_texture_dimension_2d of 8192 (it has 2048)"]
        } else {
            &[]
        };
        assert_eq!(missing, expected, "{}", record.name);
    }
}

/// Every chapter draws on an adapter with WebGPU's default limits (tests
/// here run with exactly those), and the ones that say they run on WebGL2
/// (01 to 04) need no feature, no capability WebGL2 may lack, and no
/// more of its limits than that the terrain fits.
#[test]
fn every_chapter_fits_webgpu_defaults_and_01_to_04_fit_webgl2() {
    for record in snapshots::chapters() {
        let needs = (record.needs)();
        let on_webgpu = needs.missing_on(wgpu::Features::all(), wgpu::DownlevelFlags::all(), &wgpu::Limits::defaults());
        assert!(on_webgpu.is_empty(), "{} needs more than WebGPU's defaults: {on_webgpu:?}", record.name);
        if ["triangle", "camera", "terrain", "fog"].contains(&record.name) {
            // An adapter with no optional feature and no downlevel capability.
            let on_webgl2 = record.lacks_on_webgl2();
            assert!(on_webgl2.is_empty(), "{} asks WebGL2 for {on_webgl2:?}", record.name);
        }
    }
}
