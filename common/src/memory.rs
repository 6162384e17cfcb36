//! How much memory a running chapter holds: the process's (its resident
//! set, or a page's WebAssembly heap), its heap's (the bytes its allocator
//! has handed out and not taken back) and the GPU's (the bytes of every
//! buffer and texture the device holds). The overlay shows both, the
//! window test's probe reports them, `--bench` measures how they change
//! over its frames, and `cargo xtask test` fails a chapter whose memory
//! grows frame after frame (`crate::leak` judges it).

/// Memory in use now, in bytes; `None` where this platform cannot say.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct MemoryUse {
    /// The process's resident memory on the desktop (`VmRSS` on Linux); in
    /// a browser, the bytes allocated and not yet freed, counted by the
    /// page's allocator (the WebAssembly heap itself only ever grows).
    pub process: Option<u64>,
    /// The bytes the program's allocator has handed out and not taken back
    /// ([`Counting`], the global allocator on every platform). Exact: a
    /// leak of a few kilobytes a frame shows byte for byte, where the
    /// resident set hides it behind pages freed earlier and jitters as the
    /// allocator takes and returns arenas. What a C library allocates (a
    /// driver's own memory) is not in it; `process` and `gpu` watch that.
    pub heap: Option<u64>,
    /// The bytes of every buffer and texture alive on the device, counted
    /// by wgpu (its `counters` feature) where the backend keeps the count:
    /// Vulkan and DX12. On a software rasteriser this memory is also part
    /// of `process`; on a graphics card it is not.
    pub gpu: Option<u64>,
}

impl MemoryUse {
    /// What `device` and this process hold now.
    pub fn now(device: &wgpu::Device) -> Self {
        Self { process: process_bytes(), heap: Some(heap_bytes()), gpu: gpu_bytes(device) }
    }

    /// "412 MB process, 38.2 MB GPU" for the overlay.
    pub fn describe(&self) -> String {
        let mb = |bytes: Option<u64>| bytes.map_or("n/a".into(), |b| format!("{:.1} MB", b as f64 / 1e6));
        let process = if cfg!(target_arch = "wasm32") { "live heap" } else { "process" };
        format!("{} {process}, {} GPU buffers + textures", mb(self.process), mb(self.gpu))
    }
}

impl MemoryUse {
    /// `memory=BYTES heap=BYTES gpu=BYTES` (or `n/a`) for the window test's
    /// probe line.
    pub fn probe_fields(&self) -> String {
        let value = |v: Option<u64>| v.map_or("n/a".into(), |v| v.to_string());
        format!("memory={} heap={} gpu={}", value(self.process), value(self.heap), value(self.gpu))
    }

    /// Reads back [`MemoryUse::probe_fields`] from a probe line; `None` when
    /// the line has no such fields.
    pub fn from_probe(line: &str) -> Option<Self> {
        let field = |name: &str| line.split_whitespace().find_map(|w| w.strip_prefix(name));
        let value = |w: &str| if w == "n/a" { Some(None) } else { w.parse().ok().map(Some) };
        Some(Self { process: value(field("memory=")?)?, heap: value(field("heap=")?)?, gpu: value(field("gpu=")?)? })
    }
}

/// Buffers and textures alive on `device`, by wgpu's count; `None` when
/// the backend keeps no count (it then reports zero for both).
pub fn gpu_bytes(device: &wgpu::Device) -> Option<u64> {
    let hal = device.get_internal_counters().hal;
    let bytes = hal.buffer_memory.read() + hal.texture_memory.read();
    (bytes > 0).then_some(bytes as u64)
}

/// The process's resident memory now (not its peak), where the system says.
#[cfg(not(target_arch = "wasm32"))]
pub fn process_bytes() -> Option<u64> {
    status_bytes("VmRSS:")
}

/// The most memory this process has held at once so far, in bytes (its
/// peak resident set, `VmHWM`), where the system says; `None` elsewhere.
pub fn peak_process_bytes() -> Option<u64> {
    status_bytes("VmHWM:")
}

/// A size in `/proc/self/status` (Linux), in bytes.
fn status_bytes(field: &str) -> Option<u64> {
    let status = std::fs::read_to_string("/proc/self/status").ok()?;
    let line = status.lines().find(|l| l.starts_with(field))?;
    let kib: u64 = line.split_whitespace().nth(1)?.parse().ok()?;
    Some(kib * 1024)
}

/// The page's live heap: bytes allocated and not yet freed, as its
/// allocator counts them ([`Counting`]).
#[cfg(target_arch = "wasm32")]
pub fn process_bytes() -> Option<u64> {
    Some(heap_bytes())
}

/// Bytes this program's allocator has handed out and not taken back.
pub fn heap_bytes() -> u64 {
    ALLOCATOR.live() as u64
}

/// The program's allocator: the system's (glibc's malloc on Linux,
/// dlmalloc on wasm32), counting.
#[global_allocator]
static ALLOCATOR: Counting<std::alloc::System> = Counting::new(std::alloc::System);

/// An allocator that counts the bytes it has handed out and not taken
/// back. Neither a page's WebAssembly heap (which only grows: memory a page
/// frees stays in it for the allocator to hand out again, so its size
/// would hide a leak behind the largest moment so far) nor a process's
/// resident set (which reuses freed pages before taking new ones) shows a
/// small leak at once; this count does. Every chapter allocates through
/// one (it is the global allocator) and reports its count.
pub struct Counting<A> {
    inner: A,
    live: std::sync::atomic::AtomicUsize,
}

impl<A> Counting<A> {
    pub const fn new(inner: A) -> Self {
        Self { inner, live: std::sync::atomic::AtomicUsize::new(0) }
    }

    /// Bytes allocated and not yet freed.
    pub fn live(&self) -> usize {
        self.live.load(std::sync::atomic::Ordering::Relaxed)
    }
}

// SAFETY: every call goes to `inner` with the caller's arguments; the count
// is only bookkeeping beside it.
unsafe impl<A: std::alloc::GlobalAlloc> std::alloc::GlobalAlloc for Counting<A> {
    unsafe fn alloc(&self, layout: std::alloc::Layout) -> *mut u8 {
        let pointer = unsafe { self.inner.alloc(layout) };
        if !pointer.is_null() {
            self.live.fetch_add(layout.size(), std::sync::atomic::Ordering::Relaxed);
        }
        pointer
    }

    unsafe fn alloc_zeroed(&self, layout: std::alloc::Layout) -> *mut u8 {
        let pointer = unsafe { self.inner.alloc_zeroed(layout) };
        if !pointer.is_null() {
            self.live.fetch_add(layout.size(), std::sync::atomic::Ordering::Relaxed);
        }
        pointer
    }

    unsafe fn dealloc(&self, pointer: *mut u8, layout: std::alloc::Layout) {
        unsafe { self.inner.dealloc(pointer, layout) };
        self.live.fetch_sub(layout.size(), std::sync::atomic::Ordering::Relaxed);
    }

    unsafe fn realloc(&self, pointer: *mut u8, layout: std::alloc::Layout, new_size: usize) -> *mut u8 {
        let moved = unsafe { self.inner.realloc(pointer, layout, new_size) };
        if !moved.is_null() {
            self.live.fetch_add(new_size, std::sync::atomic::Ordering::Relaxed);
            self.live.fetch_sub(layout.size(), std::sync::atomic::Ordering::Relaxed);
        }
        moved
    }
}

/// Three readings of memory, `frames[0]` and then `frames[1]` frames
/// apart: how it changed over a `--bench` run, for its tables (the tests
/// judge leaks with [`crate::leak`], over every frame). A leak grows memory between every two readings; a one-off
/// allocation (a cache filled, an allocator taking a bigger arena) grows it
/// between two of them only. So the steady growth is the smaller of the two.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Growth {
    pub readings: [MemoryUse; 3],
    pub frames: [u64; 2],
}

impl Growth {
    /// Bytes a frame the process grew by steadily (negative: it shrank).
    pub fn process_per_frame(&self) -> Option<f64> {
        self.steady(|m| m.process)
    }

    /// Bytes a frame the GPU's buffers and textures grew by steadily.
    pub fn gpu_per_frame(&self) -> Option<f64> {
        self.steady(|m| m.gpu)
    }

    fn steady(&self, read: impl Fn(&MemoryUse) -> Option<u64>) -> Option<f64> {
        let [a, b, c] = self.readings.map(|m| read(&m).map(|v| v as f64));
        let [n, m] = self.frames.map(|f| f.max(1) as f64);
        Some(((b? - a?) / n).min((c? - b?) / m))
    }

    /// Every reading, for a failure's message:
    /// `memory: process A B C bytes, gpu D E F bytes, after N and M frames`.
    pub fn line(&self) -> String {
        let values = |read: fn(&MemoryUse) -> Option<u64>| {
            self.readings.iter().map(|m| read(m).map_or("n/a".into(), |v| v.to_string())).collect::<Vec<_>>().join(" ")
        };
        format!(
            "memory: process {} bytes, gpu {} bytes, after {} and {} frames",
            values(|m| m.process),
            values(|m| m.gpu),
            self.frames[0],
            self.frames[1]
        )
    }

    /// For the bench tables: the last reading and the steady growth,
    /// `memory: process 107.0 MB (+0.0 KB a frame), GPU 7.6 MB (+0.0 KB a
    /// frame), over 33 + 33 frames`.
    pub fn summary(&self) -> String {
        let part = |name: &str, last: Option<u64>, per_frame: Option<f64>| match (last, per_frame) {
            (Some(last), Some(growth)) => {
                format!("{name} {:.1} MB ({:+.1} KB a frame)", last as f64 / 1e6, growth / 1024.0)
            }
            (Some(last), None) => format!("{name} {:.1} MB", last as f64 / 1e6),
            _ => format!("{name} not measured"),
        };
        format!(
            "memory: {}, {}, over {} + {} frames",
            part("process", self.readings[2].process, self.process_per_frame()),
            part("GPU", self.readings[2].gpu, self.gpu_per_frame()),
            self.frames[0],
            self.frames[1]
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn reading(process: u64, gpu: Option<u64>) -> MemoryUse {
        MemoryUse { process: Some(process), heap: None, gpu }
    }

    #[test]
    fn readings_are_summed_up_as_steady_growth() {
        let growth = Growth {
            readings: [reading(100_000, Some(4096)), reading(130_000, None), reading(160_000, Some(4096))],
            frames: [15, 15],
        };
        assert_eq!(growth.process_per_frame(), Some(2000.0));
        assert_eq!(growth.gpu_per_frame(), None, "no count in the middle reading");
        assert_eq!(
            growth.line(),
            "memory: process 100000 130000 160000 bytes, gpu 4096 n/a 4096 bytes, after 15 and 15 frames"
        );
        assert_eq!(growth.summary(), "memory: process 0.2 MB (+2.0 KB a frame), GPU 0.0 MB, over 15 + 15 frames");
    }

    /// A page's frames through the counting allocator: one that frees what
    /// it takes leaves the count flat, however much it took (the heap's
    /// size would have grown to its largest moment); one that keeps 16 KB
    /// a frame is a leak to the browser test's judge.
    #[test]
    fn the_counting_allocator_sees_a_page_leak_the_heap_size_hides() {
        use std::alloc::{GlobalAlloc as _, Layout, System};
        let (big, small) =
            (Layout::from_size_align(4 << 20, 8).unwrap(), Layout::from_size_align(16 << 10, 8).unwrap());
        let frames = 0..=crate::leak::WATCHED_FRAMES;
        // SAFETY (both pages): each pointer is freed with the layout it was made with.
        let tidy = Counting::new(System);
        let flat: Vec<(u64, u64)> = frames
            .clone()
            .map(|frame| unsafe {
                let scratch = tidy.alloc(big);
                let scratch = tidy.realloc(scratch, big, 2 * big.size());
                tidy.dealloc(scratch, Layout::from_size_align(2 * big.size(), 8).unwrap());
                (frame, tidy.live() as u64)
            })
            .collect();
        assert_eq!(crate::leak::growth_per_frame(&flat), Some(0.0));
        assert_eq!(tidy.live(), 0, "every byte given back is counted back");
        let leaky = Counting::new(System);
        let mut kept = Vec::new();
        let leaking: Vec<(u64, u64)> = frames
            .map(|frame| {
                kept.push(unsafe { leaky.alloc(small) });
                (frame, leaky.live() as u64)
            })
            .collect();
        let growth = crate::leak::growth_per_frame(&leaking).unwrap();
        assert_eq!(growth, 16384.0);
        assert!(growth > crate::leak::LEAK_BOUND);
        for pointer in kept {
            unsafe { leaky.dealloc(pointer, small) };
        }
        assert_eq!(leaky.live(), 0);
    }

    /// Every way in moves the count by the bytes given or taken back, as
    /// the layouts say (worked out here, not read from the allocator):
    /// `alloc`, `alloc_zeroed` (what `vec![0; n]` uses), `realloc` up and
    /// down, `dealloc`. A way in that forgot to count would leave a leak
    /// through it unseen.
    #[test]
    fn every_way_in_and_out_is_counted() {
        use std::alloc::{GlobalAlloc as _, Layout, System};
        let counting = Counting::new(System);
        let layout = |bytes| Layout::from_size_align(bytes, 16).unwrap();
        // SAFETY: each pointer is freed or resized with the layout it was made with.
        unsafe {
            let a = counting.alloc(layout(1000));
            assert_eq!(counting.live(), 1000);
            let zeroed = counting.alloc_zeroed(layout(4096));
            assert_eq!(counting.live(), 5096);
            assert!(std::slice::from_raw_parts(zeroed, 4096).iter().all(|&b| b == 0));
            let grown = counting.realloc(a, layout(1000), 3000);
            assert_eq!(counting.live(), 7096);
            let shrunk = counting.realloc(grown, layout(3000), 10);
            assert_eq!(counting.live(), 4106);
            counting.dealloc(shrunk, layout(10));
            counting.dealloc(zeroed, layout(4096));
        }
        assert_eq!(counting.live(), 0);
    }

    /// The program's own allocator is the counting one: a block taken
    /// through the global allocator (zeroed, as `vec![0; n]` takes it, and
    /// grown) shows in [`heap_bytes`]. Other tests run beside this one, so
    /// the blocks are large and the margin a few megabytes.
    #[test]
    fn the_global_allocator_is_the_counting_one() {
        const MIB: i64 = 1 << 20;
        // Each step's change in the count, within a few megabytes of what
        // it should be; tried a few times, since a test beside this one can
        // allocate or free megabytes at any moment. A way in left uncounted
        // misses by the whole block every time.
        let steps = || {
            let before = heap_bytes() as i64;
            let mut block = vec![0u8; 64 << 20];
            let zeroed = heap_bytes() as i64 - before;
            block.resize(128 << 20, 1);
            let grown = heap_bytes() as i64 - before;
            drop(block);
            let freed = heap_bytes() as i64 - before;
            [zeroed - 64 * MIB, grown - 128 * MIB, freed]
        };
        let tries: Vec<[i64; 3]> = (0..5).map(|_| steps()).collect();
        assert!(
            tries.iter().any(|misses| misses.iter().all(|miss| miss.abs() < 8 * MIB)),
            "the count missed the blocks by {tries:?} bytes"
        );
    }

    #[test]
    fn a_one_off_step_is_not_a_leak() {
        let step = Growth {
            readings: [reading(100, None), reading(36_000_100, None), reading(36_000_100, None)],
            frames: [20, 20],
        };
        assert_eq!(step.process_per_frame(), Some(0.0));
        let leak =
            Growth { readings: [reading(0, None), reading(20_000, None), reading(60_000, None)], frames: [20, 40] };
        assert_eq!(leak.process_per_frame(), Some(1000.0));
    }
}
