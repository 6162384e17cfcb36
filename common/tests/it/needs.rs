//! A chapter declares what it needs of a less-than-WebGPU adapter
//! (`GpuNeeds::downlevel`); on an adapter without it, setup stops with one
//! line naming what is missing, which the binary prints before exiting
//! with 2 (`common::cli`), never a panic.

use common::{Gpu, GpuNeeds, NoAdapter, wgpu};

#[test]
fn an_adapter_without_what_a_chapter_needs_is_refused_in_one_line() {
    // OpenGL (llvmpipe's GL 4.5, from Debian's libegl1 libegl-mesa0
    // libgles2 libgl1-mesa-dri) is less than WebGPU: it cannot view a
    // texture in another format, for one. Vulkan's lavapipe has every flag.
    let gpu = Gpu::headless_on(wgpu::Backends::GL, GpuNeeds::default()).expect("an OpenGL adapter");
    let lacking = wgpu::DownlevelFlags::all() - gpu.adapter.get_downlevel_capabilities().flags;
    assert!(lacking.contains(wgpu::DownlevelFlags::VIEW_FORMATS), "OpenGL lacks only {lacking:?}");
    let needs = GpuNeeds { downlevel: lacking, ..Default::default() };
    let Err(refusal) = Gpu::headless_on(wgpu::Backends::GL, needs) else {
        panic!("an adapter lacking {lacking:?} was used")
    };
    let line = refusal.to_string();
    assert_eq!(line.lines().count(), 1, "{line}");
    for (name, _) in lacking.iter_names() {
        assert!(line.contains(name), "the refusal does not name {name}: {line}");
    }
    // What it has is not named: a learner is told only what to look for.
    for (name, _) in gpu.adapter.get_downlevel_capabilities().flags.iter_names() {
        assert!(!line.split([' ', ',', ':']).any(|word| word == name), "{name} is named but not missing: {line}");
    }
    let _: &NoAdapter = &refusal;
}
