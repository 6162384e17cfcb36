//! Where the GPU cannot cull: what the rocks' compute pass and indirect
//! draws ask of a device (WebGL 2 has none of it, and a WebGPU device in
//! compatibility mode may lack storage buffers in vertex shaders), in one
//! line the overlay and the bench can show. Where something is missing,
//! the plain culls by chunk on the CPU.

use common::wgpu;

use crate::rock_culling::WORKGROUP_SIZE;

// ANCHOR: missing_capability
/// Why this device cannot cull the rocks on the GPU, in one line, or
/// `None` where it can: the path needs compute shaders, storage buffers
/// that vertex shaders read, and draws whose arguments come from a buffer
/// (all three missing on WebGL 2), and limits that fit `rock_bytes` of rocks.
pub fn missing_capability(
    downlevel: &wgpu::DownlevelCapabilities,
    limits: &wgpu::Limits,
    rock_bytes: u64,
) -> Option<String> {
    use wgpu::DownlevelFlags as Flags;
    let needs = [
        (Flags::COMPUTE_SHADERS, "compute shaders (DownlevelFlags::COMPUTE_SHADERS)"),
        (Flags::VERTEX_STORAGE, "storage buffers in vertex shaders (DownlevelFlags::VERTEX_STORAGE)"),
        (Flags::INDIRECT_EXECUTION, "indirect draws (DownlevelFlags::INDIRECT_EXECUTION)"),
    ];
    if let Some((_, what)) = needs.iter().find(|(flag, _)| !downlevel.flags.contains(*flag)) {
        return Some(format!("this GPU has no {what}"));
    }
    if limits.max_storage_buffers_per_shader_stage < 4 {
        return Some(format!(
            "this GPU allows {} storage buffers per shader stage, the culling needs 4",
            limits.max_storage_buffers_per_shader_stage
        ));
    }
    if limits.max_compute_invocations_per_workgroup < WORKGROUP_SIZE
        || limits.max_compute_workgroup_size_x < WORKGROUP_SIZE
    {
        return Some(format!("this GPU has no compute workgroups of {WORKGROUP_SIZE}"));
    }
    if limits.max_storage_buffer_binding_size < rock_bytes {
        return Some(format!(
            "this GPU binds at most {} MB of storage, the rocks are {} MB",
            limits.max_storage_buffer_binding_size / 1_000_000,
            rock_bytes / 1_000_000
        ));
    }
    None
}
// ANCHOR_END: missing_capability

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn each_missing_capability_is_named() {
        let full = wgpu::DownlevelCapabilities::default();
        let limits = wgpu::Limits::default();
        assert_eq!(missing_capability(&full, &limits, 32_000_000), None);
        for (flag, words) in [
            (wgpu::DownlevelFlags::COMPUTE_SHADERS, "compute shaders"),
            (wgpu::DownlevelFlags::VERTEX_STORAGE, "storage buffers in vertex shaders"),
            (wgpu::DownlevelFlags::INDIRECT_EXECUTION, "indirect draws"),
        ] {
            let lacking = wgpu::DownlevelCapabilities { flags: full.flags - flag, ..full.clone() };
            let line = missing_capability(&lacking, &limits, 32_000_000).expect("a missing flag is named");
            assert!(line.contains(words) && !line.contains('\n'), "{line}");
        }
        // WebGL 2's limits: no storage buffers at all.
        let webgl = wgpu::Limits::downlevel_webgl2_defaults();
        assert!(missing_capability(&full, &webgl, 32_000_000).unwrap().contains("0 storage buffers"));
        let small = wgpu::Limits { max_storage_buffer_binding_size: 16 << 20, ..limits };
        assert!(missing_capability(&full, &small, 32_000_000).unwrap().contains("the rocks are 32 MB"));
    }
}
