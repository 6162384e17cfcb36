//! Memory against map size, as the Mars project measured it (its heap: 1.9
//! MB for a map of 4 × 4 sections, 29 MB for 12 × 12): the plain made on
//! maps of 1025², 2049² and 4097² heights, each on a device of its own, and
//! the bytes it holds, by our own count of its buffers and by wgpu's count
//! of everything the device gained (`common::memory`).

use common::headless::OFFSCREEN_FORMAT;
use common::memory::gpu_bytes;
use common::{Gpu, anyhow, wgpu};
use terrain::TerrainData;
use terrain::heightfield::TerrainSettings;

use crate::mars_plain::{MarsPlain, gpu_needs};

// ANCHOR: map_memory
/// What the plain holds on one map.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct MapMemory {
    /// Heights along one side of the map.
    pub samples: u32,
    pub chunks: u32,
    pub rocks: u32,
    /// The height field, on the CPU: 4 bytes a height.
    pub heights: u64,
    /// On the GPU: the terrain's height and normal maps, and the patch grid's indices.
    pub terrain: u64,
    /// On the GPU: the rock's three meshes, the instances, the one-per-draw
    /// slots, and the level numbers the GPU's culling shares between
    /// pictures (each picture's lists come on top: `PlainViewpoint`).
    pub rock_bytes: u64,
    /// Everything the device gained, buffers and textures, by wgpu's count;
    /// `None` where the backend keeps none.
    pub counted: Option<u64>,
}

impl MapMemory {
    /// Makes the plain on a map of `chunks_per_side` × `chunks_per_side`
    /// chunks, on a new device, and measures what it holds.
    pub fn measure(chunks_per_side: u32) -> anyhow::Result<Self> {
        let gpu = Gpu::headless(gpu_needs())?;
        let before = gpu_bytes(&gpu.device).unwrap_or(0);
        let settings = TerrainSettings { chunks_per_side, ..Default::default() };
        let plain = MarsPlain::new(&gpu, OFFSCREEN_FORMAT, TerrainData::get(&gpu, settings))?;
        // Buffers made with contents go up through staging buffers of the
        // same size, freed once the queue has copied them: count after that.
        gpu.queue.submit([]);
        gpu.device.poll(wgpu::PollType::wait_indefinitely())?;
        let counted = gpu_bytes(&gpu.device).map(|after| after - before);
        let (terrain, rock_bytes) = plain.gpu_bytes();
        let field = plain.terrain.field();
        Ok(Self {
            samples: field.size,
            chunks: chunks_per_side,
            rocks: plain.rocks_placed(),
            heights: (field.heights.len() * std::mem::size_of::<f32>()) as u64,
            terrain,
            rock_bytes,
            counted,
        })
    }
}
// ANCHOR_END: map_memory

impl MapMemory {
    /// One row of the book's table, sizes in MB.
    pub fn row(&self) -> String {
        let mb = |bytes: u64| format!("{:.1}", bytes as f64 / 1e6);
        format!(
            "| {0}² | {1} × {1} | {2} | {3} | {4} | {5} | {6} |",
            self.samples,
            self.chunks,
            common::book_figures::thousands(self.rocks.into()),
            mb(self.heights),
            mb(self.terrain),
            mb(self.rock_bytes),
            self.counted.map_or("n/a".into(), mb)
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_plain_on_a_1025_map_holds_the_buffers_we_count() {
        let memory = MapMemory::measure(16).unwrap();
        eprintln!("{}", memory.row());
        assert_eq!((memory.samples, memory.rocks), (1025, 62_500));
        assert_eq!(memory.heights, 4 * 1025 * 1025);
        // Worked out here, not read from the buffers: 4 bytes of height and
        // 2 of normal for each of the 1025 × 1025 samples, the patch grid's
        // 16-bit indices (32 × 32 quads, 6 indices each); 32 bytes a rock;
        // the three meshes, flat-shaded, of 20, 8 and 4 triangles, three
        // vertices of 32 bytes and three 32-bit indices a triangle; and
        // 20,000 uniform slots of 32 bytes and 3 level numbers of 16, each
        // padded to the device's alignment for uniform offsets (32 bytes on
        // lavapipe, 256 on many GPUs).
        let terrain = (4 + 2) * 1025 * 1025 + 2 * 6 * 32 * 32;
        assert_eq!(memory.terrain, terrain);
        let slots = memory.rock_bytes - (32 * 62_500 + (20 + 8 + 4) * 3 * (32 + 4));
        assert!(
            slots.is_multiple_of(20_003) && [32, 64, 128, 256].contains(&(slots / 20_003)),
            "{slots} bytes of slots"
        );
        // wgpu counts every buffer and texture the plain made, as the
        // driver allocated them: ours, the uniforms on top (a few
        // kilobytes), and the padding a driver may give each row of a
        // texture (lavapipe's comes to about 2 % of the terrain's maps).
        if let Some(counted) = memory.counted {
            let ours = memory.terrain + memory.rock_bytes;
            let slack = 64 * 1024 + memory.terrain / 32;
            assert!(counted >= ours && counted - ours < slack, "wgpu counts {counted} bytes, we {ours}");
        }
    }

    #[test]
    fn a_picture_holds_three_lists_of_four_bytes_a_rock() {
        let gpu = Gpu::headless(gpu_needs()).unwrap();
        let settings = TerrainSettings { chunks_per_side: 16, ..Default::default() };
        let plain = MarsPlain::new(&gpu, OFFSCREEN_FORMAT, TerrainData::get(&gpu, settings)).unwrap();
        let bytes = plain.viewpoint_bytes(&plain.viewpoint(&gpu.device));
        // Three lists of 62,500 rocks, 4 bytes each, and on top a few
        // hundred bytes: the draws and their read-back copies, the uniform,
        // the alignment of each list, the CPU's draw list (20 bytes a group).
        let lists = 3 * 62_500 * 4;
        assert!(bytes >= lists && bytes - lists < 16 * 1024, "{bytes} bytes");
    }

    /// The book's table, by hand (4097² takes a while in a debug build):
    /// `cargo test -p instancing --release -- --ignored memory_table --nocapture`.
    #[test]
    #[ignore]
    fn memory_table() {
        for chunks in [16, 32, 64] {
            println!("{}", MapMemory::measure(chunks).unwrap().row());
        }
    }
}
