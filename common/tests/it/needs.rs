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

/// Every device is opened with WebGPU's default limits, not the adapter's
/// (lavapipe allows 8 bind groups and far more storage buffers than
/// WebGPU's 4 and 8): a layout that asks for one more than a learner's
/// adapter must give fails here, in wgpu's words, which name the limit.
#[test]
fn a_layout_past_webgpu_limits_fails_here_naming_the_limit() {
    let gpu = Gpu::headless(GpuNeeds::default()).expect("an adapter (lavapipe will do)");
    let device = &gpu.device;
    let empty = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor { label: None, entries: &[] });
    let groups = |count: usize| {
        gpu.catch_validation(|| {
            device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
                label: None,
                bind_group_layouts: &vec![Some(&empty); count],
                immediate_size: 0,
            })
        })
    };
    assert!(groups(4).is_ok(), "WebGPU allows 4 bind groups");
    let error = groups(5).expect_err("a fifth bind group was allowed");
    assert!(error.contains("bind group limit 4"), "{error}");

    let storage = |count: u32| {
        let entries: Vec<_> = (0..count)
            .map(|binding| wgpu::BindGroupLayoutEntry {
                binding,
                visibility: wgpu::ShaderStages::FRAGMENT,
                ty: wgpu::BindingType::Buffer {
                    ty: wgpu::BufferBindingType::Storage { read_only: true },
                    has_dynamic_offset: false,
                    min_binding_size: None,
                },
                count: None,
            })
            .collect();
        gpu.catch_validation(|| {
            device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor { label: None, entries: &entries })
        })
    };
    assert!(storage(8).is_ok(), "WebGPU allows 8 storage buffers a fragment stage");
    let error = storage(9).expect_err("a ninth fragment-stage storage buffer was allowed");
    assert!(error.contains("max_storage_buffers_per_shader_stage"), "{error}");
}

/// What an adapter lacks of a chapter's limits is named with both values,
/// beside its missing features and capabilities, and nothing it has is.
#[test]
fn each_missing_limit_is_named_with_what_is_needed_and_what_there_is() {
    let needs = GpuNeeds {
        required: wgpu::Features::CLIP_DISTANCES,
        downlevel: wgpu::DownlevelFlags::COMPUTE_SHADERS,
        limits: wgpu::Limits { max_texture_dimension_2d: 4097, ..wgpu::Limits::downlevel_webgl2_defaults() },
        ..Default::default()
    };
    let small = wgpu::Limits { max_texture_dimension_2d: 2048, ..wgpu::Limits::downlevel_webgl2_defaults() };
    let missing = needs.missing_on(wgpu::Features::empty(), wgpu::DownlevelFlags::empty(), &small);
    assert_eq!(
        missing,
        ["the features CLIP_DISTANCES", "COMPUTE_SHADERS", "max_texture_dimension_2d of 4097 (it has 2048)"]
    );
    let enough = wgpu::Limits { max_texture_dimension_2d: 4097, ..small };
    assert!(needs.missing_on(wgpu::Features::all(), wgpu::DownlevelFlags::all(), &enough).is_empty());
    // A limit where less is better (an alignment) is short when larger.
    let coarse = wgpu::Limits { min_uniform_buffer_offset_alignment: 512, ..enough };
    assert_eq!(
        needs.missing_on(wgpu::Features::all(), wgpu::DownlevelFlags::all(), &coarse),
        ["min_uniform_buffer_offset_alignment of 256 (it has 512)"]
    );
}

/// The device gets WebGPU's defaults, raised to a chapter's needs and
/// lowered to what the adapter has, never the adapter's own.
#[test]
fn a_device_gets_webgpu_limits_raised_to_needs_and_lowered_to_the_adapter() {
    let needs = GpuNeeds {
        limits: wgpu::Limits { max_bind_groups: 6, ..wgpu::Limits::downlevel_webgl2_defaults() },
        ..Default::default()
    };
    let generous = wgpu::Limits { max_bind_groups: 8, max_storage_buffers_per_shader_stage: 64, ..Default::default() };
    let limits = needs.device_limits(&generous);
    assert_eq!((limits.max_bind_groups, limits.max_storage_buffers_per_shader_stage), (6, 8));
    let webgl2 = wgpu::Limits::downlevel_webgl2_defaults();
    assert_eq!(GpuNeeds::default().device_limits(&webgl2), webgl2);
}
