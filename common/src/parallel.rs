//! Splitting independent work across the CPU's cores. Chapters call this
//! instead of spawning threads, so that where threads are missing (a
//! browser's main thread) the same code simply runs the bands in turn.

use std::ops::Range;

/// Runs `work` on bands of `0..items`, one band per core, and returns the
/// bands' results concatenated in order: the same output as
/// `work(0..items)`, sooner. `work` must only depend on the range it is given.
pub fn map_bands<T: Send>(items: usize, work: impl Fn(Range<usize>) -> Vec<T> + Sync) -> Vec<T> {
    let threads =
        if cfg!(target_arch = "wasm32") { 1 } else { std::thread::available_parallelism().map_or(1, |n| n.get()) };
    let band = items.div_ceil(threads).max(1);
    let ranges: Vec<Range<usize>> = (0..items).step_by(band).map(|start| start..(start + band).min(items)).collect();
    if ranges.len() <= 1 {
        return work(0..items);
    }
    let work = &work;
    let bands: Vec<Vec<T>> = std::thread::scope(|scope| {
        let handles: Vec<_> = ranges.into_iter().map(|range| scope.spawn(move || work(range))).collect();
        handles.into_iter().map(|h| h.join().unwrap_or_else(|panic| std::panic::resume_unwind(panic))).collect()
    });
    let mut all = Vec::with_capacity(bands.iter().map(Vec::len).sum());
    for band in bands {
        all.extend(band);
    }
    all
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn bands_concatenate_in_order() {
        for items in [0, 1, 2, 7, 1000] {
            let squares = map_bands(items, |range| range.map(|i| i * i).collect());
            assert_eq!(squares, (0..items).map(|i| i * i).collect::<Vec<_>>(), "{items} items");
        }
    }
}
