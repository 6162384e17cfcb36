//! Reading back what the GPU wrote: the CPU does not know how many rocks
//! the GPU's culling kept until it copies the counts into a buffer it may
//! map. At once, waiting for the GPU (`read_buffer`: for `--bench` and the
//! tests), or a frame or two late without ever waiting (`LateCounts`: for
//! the overlay, every frame).

use std::sync::Arc;
use std::sync::atomic::{AtomicBool, Ordering};

use common::{Gpu, wgpu};

/// The first `bytes` of `buffer` (which has `COPY_SRC`), waiting for the
/// GPU to finish what was submitted: through a buffer the CPU can map.
pub(crate) fn read_buffer(gpu: &Gpu, buffer: &wgpu::Buffer, bytes: u64) -> Vec<u32> {
    let readback = gpu.device.create_buffer(&wgpu::BufferDescriptor {
        label: Some("read back"),
        size: bytes,
        usage: wgpu::BufferUsages::MAP_READ | wgpu::BufferUsages::COPY_DST,
        mapped_at_creation: false,
    });
    let mut encoder = gpu.device.create_command_encoder(&Default::default());
    encoder.copy_buffer_to_buffer(buffer, 0, &readback, 0, bytes);
    gpu.queue.submit([encoder.finish()]);
    let slice = readback.slice(..);
    slice.map_async(wgpu::MapMode::Read, |_| {});
    if gpu.device.poll(wgpu::PollType::wait_indefinitely()).is_err() {
        return vec![0; (bytes / 4) as usize];
    }
    let values = match slice.get_mapped_range() {
        Ok(view) => bytemuck::cast_slice(&view).to_vec(),
        Err(_) => vec![0; (bytes / 4) as usize],
    };
    readback.unmap();
    values
}

// ANCHOR: late_counts
/// A small buffer's words (a picture's indirect draws, whose instance
/// counts the GPU wrote), copied each frame into one of a few buffers the
/// CPU can map, and read once the GPU is done with them: a frame or two
/// late, but without ever waiting for the GPU.
pub(crate) struct LateCounts {
    slots: [Slot; 3],
    latest: Option<Vec<u32>>,
}

struct Slot {
    buffer: wgpu::Buffer,
    state: SlotState,
    /// Set by the map's callback, which wgpu may run on another thread.
    mapped: Arc<AtomicBool>,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum SlotState {
    /// Ready for this frame's copy.
    Free,
    /// The copy is recorded; once it is submitted, the buffer can be mapped.
    Copied,
    /// Asked to be mapped; the callback says when.
    Mapping,
}

impl LateCounts {
    /// Three slots of `bytes` each.
    pub(crate) fn new(device: &wgpu::Device, bytes: u64) -> Self {
        let slot = |_| Slot {
            buffer: device.create_buffer(&wgpu::BufferDescriptor {
                label: Some("rock counts, read late"),
                size: bytes,
                usage: wgpu::BufferUsages::MAP_READ | wgpu::BufferUsages::COPY_DST,
                mapped_at_creation: false,
            }),
            state: SlotState::Free,
            mapped: Arc::default(),
        };
        Self { slots: std::array::from_fn(slot), latest: None }
    }

    /// Reads the slots the GPU has finished with, and asks to map the ones
    /// copied into last frame (submitted since). Never waits.
    pub(crate) fn collect(&mut self, device: &wgpu::Device) {
        let _ = device.poll(wgpu::PollType::Poll);
        for slot in &mut self.slots {
            match slot.state {
                SlotState::Mapping if slot.mapped.load(Ordering::Acquire) => {
                    if let Ok(view) = slot.buffer.slice(..).get_mapped_range() {
                        self.latest = Some(bytemuck::cast_slice(&view).to_vec());
                    }
                    slot.buffer.unmap();
                    slot.mapped.store(false, Ordering::Release);
                    slot.state = SlotState::Free;
                }
                SlotState::Copied => {
                    let mapped = slot.mapped.clone();
                    slot.buffer.slice(..).map_async(wgpu::MapMode::Read, move |result| {
                        mapped.store(result.is_ok(), Ordering::Release);
                    });
                    slot.state = SlotState::Mapping;
                }
                _ => {}
            }
        }
    }

    /// Records a copy of `source` into a free slot, if one is free.
    pub(crate) fn copy(&mut self, encoder: &mut wgpu::CommandEncoder, source: &wgpu::Buffer) {
        if let Some(slot) = self.slots.iter_mut().find(|slot| slot.state == SlotState::Free) {
            encoder.copy_buffer_to_buffer(source, 0, &slot.buffer, 0, slot.buffer.size());
            slot.state = SlotState::Copied;
        }
    }

    /// The words of the latest copy that has come back, if one has.
    pub(crate) fn latest(&self) -> Option<&[u32]> {
        self.latest.as_deref()
    }

    /// Bytes of the slots.
    pub(crate) fn gpu_bytes(&self) -> u64 {
        self.slots.iter().map(|slot| slot.buffer.size()).sum()
    }
}
// ANCHOR_END: late_counts
