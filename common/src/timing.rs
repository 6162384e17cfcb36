//! Measuring frames: GPU timestamps around render passes, and the
//! min/median/p95 summaries the bench prints.

use std::cell::RefCell;
// `std::time::Instant` panics in the browser; this one reads `performance.now()` there.
use web_time::Instant;

/// Hands out timestamp query slots to render passes and reads the times back.
///
/// A chapter asks `timer.pass("reflection")` when it begins a pass and puts
/// the answer into `RenderPassDescriptor::timestamp_writes`. When the
/// adapter has no timestamp queries, or nobody is measuring, the answer is
/// `None` and the pass is simply not timed; its name is still recorded, so
/// that tests can tell which passes a frame has.
pub struct PassTimer {
    queries: Option<Queries>,
    labels: RefCell<Vec<&'static str>>,
    /// CPU work timed with [`PassTimer::cpu`] this frame: (label, ms).
    cpu: RefCell<Vec<(&'static str, f64)>>,
}

struct Queries {
    set: wgpu::QuerySet,
    resolve: wgpu::Buffer,
    readback: wgpu::Buffer,
    capacity: u32,
}

impl PassTimer {
    /// A timer that never measures.
    pub fn off() -> Self {
        Self { queries: None, labels: RefCell::new(Vec::new()), cpu: RefCell::new(Vec::new()) }
    }

    /// A timer for up to `passes` passes a frame, if the device can time them.
    pub fn new(device: &wgpu::Device, passes: u32) -> Self {
        if !device.features().contains(wgpu::Features::TIMESTAMP_QUERY) {
            return Self::off();
        }
        let count = 2 * passes;
        let size = u64::from(count) * 8;
        let set = device.create_query_set(&wgpu::QuerySetDescriptor {
            label: Some("pass timestamps"),
            ty: wgpu::QueryType::Timestamp,
            count,
        });
        let resolve = device.create_buffer(&wgpu::BufferDescriptor {
            label: Some("timestamp resolve"),
            size,
            usage: wgpu::BufferUsages::QUERY_RESOLVE | wgpu::BufferUsages::COPY_SRC,
            mapped_at_creation: false,
        });
        let readback = device.create_buffer(&wgpu::BufferDescriptor {
            label: Some("timestamp readback"),
            size,
            usage: wgpu::BufferUsages::MAP_READ | wgpu::BufferUsages::COPY_DST,
            mapped_at_creation: false,
        });
        Self {
            queries: Some(Queries { set, resolve, readback, capacity: passes }),
            labels: RefCell::new(Vec::new()),
            cpu: RefCell::new(Vec::new()),
        }
    }

    pub fn is_on(&self) -> bool {
        self.queries.is_some()
    }

    /// Timestamp writes for the next pass, labelled for the report.
    pub fn pass(&self, label: &'static str) -> Option<wgpu::RenderPassTimestampWrites<'_>> {
        let mut labels = self.labels.borrow_mut();
        let index = labels.len() as u32;
        labels.push(label);
        let queries = self.queries.as_ref().filter(|q| index < q.capacity)?;
        Some(wgpu::RenderPassTimestampWrites {
            query_set: &queries.set,
            beginning_of_pass_write_index: Some(2 * index),
            end_of_pass_write_index: Some(2 * index + 1),
        })
    }

    /// Timestamp writes for the next compute pass, labelled for the report
    /// like a render pass (chapter 05's rock culling).
    pub fn compute_pass(&self, label: &'static str) -> Option<wgpu::ComputePassTimestampWrites<'_>> {
        let writes = self.pass(label)?;
        Some(wgpu::ComputePassTimestampWrites {
            query_set: writes.query_set,
            beginning_of_pass_write_index: writes.beginning_of_pass_write_index,
            end_of_pass_write_index: writes.end_of_pass_write_index,
        })
    }

    /// Timestamp writes for pass `index` of a chain of `count` passes that
    /// is reported as one, `label`: the first pass writes the beginning and
    /// the last the end, so the report shows the whole chain (a bloom's
    /// dozen small passes, say). Passes between them write nothing.
    pub fn chain(
        &self,
        label: &'static str,
        index: usize,
        count: usize,
    ) -> Option<wgpu::RenderPassTimestampWrites<'_>> {
        let first = index == 0;
        let last = index + 1 == count;
        if first {
            self.labels.borrow_mut().push(label);
        }
        let queries = self.queries.as_ref()?;
        let slot = self.labels.borrow().iter().rposition(|l| *l == label)? as u32;
        if slot >= queries.capacity || !(first || last) {
            return None;
        }
        Some(wgpu::RenderPassTimestampWrites {
            query_set: &queries.set,
            beginning_of_pass_write_index: first.then_some(2 * slot),
            end_of_pass_write_index: last.then_some(2 * slot + 1),
        })
    }

    /// Runs `work` and records how long it took on the CPU as `label`:
    /// work a frame does before the GPU sees it (culling lights, say).
    /// Chapters time nothing themselves; this is where the clock is.
    pub fn cpu<T>(&self, label: &'static str, work: impl FnOnce() -> T) -> T {
        let start = Instant::now();
        let value = work();
        self.cpu.borrow_mut().push((label, start.elapsed().as_secs_f64() * 1e3));
        value
    }

    /// The CPU work timed since the last call, as (label, ms), and forgets it.
    pub fn take_cpu(&self) -> Vec<(&'static str, f64)> {
        std::mem::take(&mut *self.cpu.borrow_mut())
    }

    /// The names of the passes begun since the last `read` or `take_labels`,
    /// in order, and forgets them.
    pub fn take_labels(&self) -> Vec<&'static str> {
        std::mem::take(&mut *self.labels.borrow_mut())
    }

    /// Records the copy of this frame's timestamps; call after the passes.
    pub fn resolve(&self, encoder: &mut wgpu::CommandEncoder) {
        let Some(queries) = &self.queries else { return };
        let used = (self.labels.borrow().len() as u32).min(queries.capacity);
        if used == 0 {
            return;
        }
        encoder.resolve_query_set(&queries.set, 0..2 * used, &queries.resolve, 0);
        encoder.copy_buffer_to_buffer(&queries.resolve, 0, &queries.readback, 0, u64::from(used) * 16);
    }

    /// Waits for the frame and returns (label, milliseconds) per timed pass,
    /// then forgets the labels for the next frame.
    pub fn read(&self, gpu: &crate::Gpu) -> Vec<(&'static str, f64)> {
        let mut labels = self.take_labels();
        let Some(queries) = &self.queries else { return Vec::new() };
        labels.truncate(queries.capacity as usize);
        if labels.is_empty() {
            return Vec::new();
        }
        let bytes = labels.len() as u64 * 16;
        let slice = queries.readback.slice(..bytes);
        slice.map_async(wgpu::MapMode::Read, |_| {});
        if gpu.device.poll(wgpu::PollType::wait_indefinitely()).is_err() {
            return Vec::new();
        }
        let period_ms = f64::from(gpu.queue.get_timestamp_period()) / 1e6;
        let times: Vec<u64> = match slice.get_mapped_range() {
            Ok(view) => bytemuck::cast_slice(&view).to_vec(),
            Err(_) => return Vec::new(),
        };
        queries.readback.unmap();
        labels
            .into_iter()
            .zip(times.chunks_exact(2))
            .map(|(label, t)| (label, t[1].saturating_sub(t[0]) as f64 * period_ms))
            .collect()
    }
}

/// Summary of a series of timings, in milliseconds.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Stats {
    pub min: f64,
    pub median: f64,
    pub p95: f64,
    pub count: usize,
}

impl Stats {
    /// Summarises `samples`; `None` when there are none.
    pub fn of(samples: &[f64]) -> Option<Self> {
        if samples.is_empty() {
            return None;
        }
        let mut sorted = samples.to_vec();
        sorted.sort_by(f64::total_cmp);
        // Nearest-rank percentile: the smallest sample with at least p% at or below it.
        let rank = |p: f64| sorted[((p * sorted.len() as f64).ceil() as usize).clamp(1, sorted.len()) - 1];
        Some(Self { min: sorted[0], median: rank(0.5), p95: rank(0.95), count: sorted.len() })
    }
}

/// Runs `work` once and says how long it took, in milliseconds: for what a
/// chapter measures outside frames (loading a model, making mipmaps).
pub fn measure<T>(work: impl FnOnce() -> T) -> (T, f64) {
    let start = Instant::now();
    let value = work();
    (value, start.elapsed().as_secs_f64() * 1e3)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn stats_use_nearest_rank() {
        let samples: Vec<f64> = (1..=100).rev().map(f64::from).collect();
        let stats = Stats::of(&samples).unwrap();
        assert_eq!((stats.min, stats.median, stats.p95, stats.count), (1.0, 50.0, 95.0, 100));
        let one = Stats::of(&[4.0]).unwrap();
        assert_eq!((one.min, one.median, one.p95), (4.0, 4.0, 4.0));
        assert!(Stats::of(&[]).is_none());
    }
}
