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
        let plain = MarsPlain::new(&gpu, OFFSCREEN_FORMAT, &[1], TerrainData::get(&gpu, settings))?;
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
    /// One row of page 05's table, sizes in MB (wgpu's count is not in it:
    /// it is the adapter's, and checked against ours by a test instead).
    pub fn row(&self) -> String {
        let mb = |bytes: u64| format!("{:.1}", bytes as f64 / 1e6);
        format!(
            "| {0}² | {1} × {1} | {2} | {3} | {4} | {5} |",
            self.samples,
            self.chunks,
            common::book_figures::thousands(self.rocks.into()),
            mb(self.heights),
            mb(self.terrain),
            mb(self.rock_bytes),
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// What the plain on a map of `chunks` × `chunks` chunks must hold,
    /// worked out from the formats rather than read from the buffers, for a
    /// device whose uniform offsets align to `alignment` bytes: 4 bytes of
    /// height and 2 of normal for each sample (chapter 03's two maps, 64
    /// quads a chunk side), the patch grid's 16-bit indices (32 × 32 quads,
    /// 6 indices each); a million rocks on the 64 × 64 map, as many a
    /// chunk on the others, 32 bytes each; the three meshes, flat-shaded,
    /// of 20, 8 and 4 triangles, three vertices of 32 bytes and three
    /// 32-bit indices a triangle; 20,000 uniform slots and 3 level numbers,
    /// each padded to the alignment.
    fn worked_out(chunks: u32, alignment: u64) -> MapMemory {
        let samples = 64 * chunks + 1;
        let heights = u64::from(samples).pow(2);
        let rocks = 1_000_000 * chunks.pow(2) / 64u32.pow(2);
        MapMemory {
            samples,
            chunks,
            rocks,
            heights: 4 * heights,
            terrain: (4 + 2) * heights + 2 * 6 * 32 * 32,
            rock_bytes: 32 * u64::from(rocks) + (20 + 8 + 4) * 3 * (32 + 4) + 20_003 * alignment,
            counted: None,
        }
    }

    #[test]
    fn the_plain_on_a_1025_map_holds_the_buffers_we_count() {
        let memory = MapMemory::measure(16).unwrap();
        eprintln!("{}", memory.row());
        // The slots' alignment is the device's (32 bytes on lavapipe, 256
        // on many GPUs): read it from what the plain holds beyond the rest.
        let slots = memory.rock_bytes - (32 * 62_500 + (20 + 8 + 4) * 3 * (32 + 4));
        let alignment = slots / 20_003;
        assert!([32, 64, 128, 256].contains(&alignment), "{slots} bytes of slots");
        assert_eq!(MapMemory { counted: None, ..memory }, worked_out(16, alignment));
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

    /// Page 05's table of the three maps is the worked-out sizes (on a
    /// device aligning uniforms to 32 bytes, as lavapipe does), so it
    /// needs none of the big maps built to stay true.
    #[test]
    fn page_05_gives_the_worked_out_sizes_of_every_map() {
        let page = common::book_figures::section_text("05-instancing");
        for chunks in [16, 32, 64] {
            let row = worked_out(chunks, 32).row();
            assert!(page.contains(&row), "page 05's memory table should have the row `{row}`");
        }
    }

    #[test]
    fn a_picture_holds_three_lists_of_four_bytes_a_rock() {
        let gpu = Gpu::headless(gpu_needs()).unwrap();
        let settings = TerrainSettings { chunks_per_side: 16, ..Default::default() };
        let plain = MarsPlain::new(&gpu, OFFSCREEN_FORMAT, &[1], TerrainData::get(&gpu, settings)).unwrap();
        let bytes = plain.viewpoint_bytes(&plain.viewpoint(&gpu.device, 1));
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
            let memory = MapMemory::measure(chunks).unwrap();
            let by_wgpu = memory.counted.map_or("n/a".into(), |bytes| format!("{:.1} MB", bytes as f64 / 1e6));
            println!("{} by wgpu: {by_wgpu}", memory.row());
        }
    }
}
