//! Telling a leak from noise. A leak grows memory frame after frame; a
//! one-off allocation (a cache filled, an allocator taking another arena, a
//! driver compiling a shader variant late) grows it once; and a process's
//! resident set jitters from reading to reading. So memory is read every
//! frame over at least [`WATCHED_FRAMES`] frames, the frames are cut into
//! [`STRETCHES`] stretches, and the growth a frame is the median of the
//! stretches' slopes: a steady leak raises every stretch's slope, a one-off
//! step only one's, so no single step (nor two) moves the median, and
//! nothing here is a minimum that a retry could only lower. Where the
//! median is over the bound, the window test watches [`MORE_WATCHED_FRAMES`]
//! frames more and the median of all the stretches decides: a leak raises
//! the new stretches too, steps only the few they fall in. Resizing the
//! window and minimising it are judged the same way, per cycle: the median
//! of the growths over [`CYCLES`] cycles.
//!
//! This file uses nothing but `std`: `cargo xtask`, which links no GPU
//! crate, compiles it too (`#[path]`), so the bounds are written once.

/// Frames memory is watched over, at least. Thirty: the live heap and
/// the GPU's buffers and textures are counted exactly, so a leak of the
/// bound a frame moves them by 240 KB over the watch; only the resident
/// set jitters, and the stretches below take care of that. (Sixty, until
/// 2026-11-29: the watch was then 60% of the window test's frames, and on
/// a software rasteriser a chapter 07 frame takes a second.)
pub const WATCHED_FRAMES: u64 = 30;

/// Stretches the watched frames are cut into: enough that two one-off
/// steps still leave the median on a quiet one.
pub const STRETCHES: usize = 6;

/// Frames in a stretch, however many frames are watched: five.
pub const STRETCH_FRAMES: u64 = WATCHED_FRAMES / STRETCHES as u64;

/// Frames in a stretch where memory is not read at every frame: a page,
/// which the browser test reads between frames it does not wait for (one
/// reading every two or three of chapter 01's frames). Every stretch needs
/// two readings, which five frames did not always hold (the browser test
/// failed "too few readings" once, 2026-11-29); ten always have. Such a
/// watch spans [`STRETCHES`] of them.
pub const SPARSE_STRETCH_FRAMES: u64 = 10;
// A sparse watch is one of longer stretches, or there is no point to it.
const _: () = assert!(SPARSE_STRETCH_FRAMES > STRETCH_FRAMES);

/// Frames watched more when the first [`WATCHED_FRAMES`] judge a leak, cut
/// into stretches of the same length. Why: a step that falls across the
/// edge between two stretches raises both, so two such steps and a third
/// raise half of six stretches and move the median. Seen in CI on
/// 2026-11-28: chapter 11's resident set rose by 0.3, 0.16 and 0.4 MB in
/// three steps of a few frames each (one across an edge), on a run of the
/// window test beside another chapter's, and its median read 8.8 KB a frame
/// while every run of it alone reads 0. The frames watched more make
/// twelve stretches, which those steps cannot move; a steady leak raises
/// them all.
pub const MORE_WATCHED_FRAMES: u64 = WATCHED_FRAMES;

/// Resize and minimise cycles the window test runs: a state left stuck by
/// one shows by the second, and the median of three growths ignores a
/// first cycle that fills a cache. Where that median is over the bound,
/// [`MORE_CYCLES`] more are run and the median of all decides: a leak grows
/// every cycle, a chance step only some (chapter 06's window now and then
/// takes 36 MB at once, at moments of its own: measured, not explained).
pub const CYCLES: usize = 3;
pub const MORE_CYCLES: usize = 2;

/// The most a chapter's memory (the process's resident set, the GPU's
/// buffers and textures) may grow by steadily, in
/// bytes a frame, before the tests call it a leak: 8 KB, 1.7 GB an hour at
/// 60 frames a second. Measured by the window test (the median of six
/// stretch slopes over 60 frames), chapters that do not leak grew by at
/// most 1.2 KB a frame, once 3.8; the leaks found so far by 1.4 to 25 MB.
pub const LEAK_BOUND: f64 = 8192.0;

/// The most the live heap (the bytes the allocator has handed out and not
/// taken back, counted exactly) may grow by steadily, in bytes a frame:
/// 1 KB, 216 MB an hour at 60 frames a second. Measured by the window test,
/// chapters that do not leak grew by at most 52 bytes a frame; a leak of
/// 9 KB a frame put back in chapter 11 read 9,244.
pub const HEAP_LEAK_BOUND: f64 = 1024.0;

/// The most the process's memory may grow by per resize through 1×1 and
/// back, or per minimise and restore, in bytes: 4 MB. Measured, chapters
/// that do not leak grew by up to 1.9 MB a resize (the median of three)
/// while lavapipe's window code kept the pictures of the first few sizes
/// (it stops after five cycles or so); the resident set cannot tell a
/// leaked 640×360 picture (0.9 MB) from that, the GPU's count can.
pub const CYCLE_BOUND: f64 = 4_194_304.0;

/// The most the live heap may grow by per cycle, in bytes: 256 KB.
/// Measured, chapters that do not leak grew by at most 63 KB a resize
/// (chapter 11; the others 13 KB) and 1.4 KB a minimise; one leaked
/// 640×360 picture is 0.9 MB.
pub const HEAP_CYCLE_BOUND: f64 = 262_144.0;

/// The most the GPU's buffers and textures may grow by per cycle, in bytes:
/// 256 KB. wgpu counts them exactly: chapters that do not leak grew by at
/// most 2 KB a cycle, and one leaked 640×360 picture is 0.9 MB.
pub const GPU_CYCLE_BOUND: f64 = 262_144.0;

/// One reading: frames drawn so far, and bytes in use then.
pub type Reading = (u64, u64);

/// The median of `values` (the mean of the middle two for an even count);
/// `None` when there are none.
pub fn median(values: &mut [f64]) -> Option<f64> {
    values.sort_by(f64::total_cmp);
    let n = values.len();
    match n {
        0 => None,
        _ if n % 2 == 1 => Some(values[n / 2]),
        _ => Some((values[n / 2 - 1] + values[n / 2]) / 2.0),
    }
}

/// The steady growth in bytes a frame of `readings` (in frame order): the
/// median of the slopes of stretches of equal frame counts, [`STRETCHES`]
/// over [`WATCHED_FRAMES`] frames and as many more of the same length as
/// more frames hold, each slope from the first reading at or after the
/// stretch's start to the last at or before its end. `None` when the
/// readings span fewer than [`WATCHED_FRAMES`] frames or a stretch has
/// fewer than two.
pub fn growth_per_frame(readings: &[Reading]) -> Option<f64> {
    growth_per_frame_in(readings, STRETCH_FRAMES)
}

/// [`growth_per_frame`] with stretches of `stretch` frames, over at least
/// [`STRETCHES`] of them ([`SPARSE_STRETCH_FRAMES`] where memory is not
/// read at every frame).
pub fn growth_per_frame_in(readings: &[Reading], stretch: u64) -> Option<f64> {
    let (first, last) = (readings.first()?.0, readings.last()?.0);
    if last - first < stretch * STRETCHES as u64 {
        return None;
    }
    let stretches = ((last - first) / stretch) as usize;
    let span = (last - first) as f64 / stretches as f64;
    let mut slopes = Vec::with_capacity(stretches);
    for k in 0..stretches {
        let (start, end) = (first as f64 + span * k as f64, first as f64 + span * (k + 1) as f64);
        let inside: Vec<&Reading> =
            readings.iter().filter(|(frame, _)| *frame as f64 >= start - 1e-9 && *frame as f64 <= end + 1e-9).collect();
        let (a, b) = (inside.first()?, inside.last()?);
        if b.0 <= a.0 {
            return None;
        }
        slopes.push((b.1 as f64 - a.1 as f64) / (b.0 - a.0) as f64);
    }
    median(&mut slopes)
}

/// What a leak found by [`growth_per_frame`] is told as: `what` grew by
/// `per_frame` bytes a frame over `frames` frames, more than `bound`.
pub fn describe(what: &str, per_frame: f64, frames: u64, bound: f64) -> String {
    format!(
        "{what} grew by {:.1} KB a frame over {frames} frames (the median of the slopes of its stretches; \
         more than {:.0} KB a frame): a leak",
        per_frame / 1024.0,
        bound / 1024.0
    )
}

/// The growth in bytes a cycle (a resize, a minimise), from memory read in
/// the same state before each cycle and after the last: the median of the
/// differences. `None` with fewer than two readings.
pub fn growth_per_cycle(readings: &[u64]) -> Option<f64> {
    let mut growths: Vec<f64> = readings.windows(2).map(|pair| pair[1] as f64 - pair[0] as f64).collect();
    median(&mut growths)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// One stretch, in frames.
    const S: u64 = STRETCH_FRAMES;

    /// A reading every frame from frame 100 over [`WATCHED_FRAMES`] frames
    /// and `more` frames more, `bytes(frame)` each.
    fn watched_more(more: u64, bytes: impl Fn(u64) -> f64) -> Vec<Reading> {
        (100..=100 + WATCHED_FRAMES + more).map(|f| (f, bytes(f).round() as u64)).collect()
    }

    fn watched(bytes: impl Fn(u64) -> f64) -> Vec<Reading> {
        watched_more(0, bytes)
    }

    #[test]
    fn a_steady_leak_is_its_slope_whatever_the_steps_and_the_jitter() {
        // 16 KB a frame, two one-off steps of 30 MB (inside the second
        // stretch and the fifth), and jitter of ±200 KB that repeats every
        // stretch.
        let jitter = |f: u64| if (f - 100).is_multiple_of(S) { 200e3 } else { -200e3 };
        let step = |f: u64| if f >= 100 + S + 2 { 30e6 } else { 0.0 } + if f >= 100 + 4 * S + 3 { 30e6 } else { 0.0 };
        let leak = watched(|f| 500e6 + 16384.0 * (f - 100) as f64 + step(f) + jitter(f));
        let growth = growth_per_frame(&leak).unwrap();
        // Each stretch runs between two readings of the same jitter: it
        // cancels, and the steps stay in theirs.
        assert!((growth - 16384.0).abs() < 1.0, "{growth}");
        assert!(growth > LEAK_BOUND);
    }

    #[test]
    fn one_off_steps_and_jitter_are_not_a_leak() {
        // Pages of 4 KB taken and given back, up to 16 KB, with no trend
        // (a stretch's slope then errs by at most 16 KB over five frames,
        // under the bound), and two steps of 36 MB and 9 MB.
        let noise = |f: u64| ((f * 7919) % 5) as f64 * 4096.0;
        let steps = watched(|f| {
            400e6 + if f > 100 + 2 * S { 36e6 } else { 0.0 } + if f >= 100 + 4 * S + 2 { 9e6 } else { 0.0 } + noise(f)
        });
        let growth = growth_per_frame(&steps).unwrap();
        assert!(growth.abs() <= LEAK_BOUND, "{growth}");
        // The minimum of the stretches would hide a leak under one quiet
        // stretch: the median does not.
        let mut quiet_once = watched(|f| 16384.0 * (f - 100) as f64);
        let (from, to) = (100 + 3 * S, 100 + 4 * S);
        for reading in quiet_once.iter_mut().filter(|(f, _)| (from..=to).contains(f)) {
            reading.1 = 16384 * (from - 100);
        }
        assert!(growth_per_frame(&quiet_once).unwrap() > LEAK_BOUND);
    }

    #[test]
    fn steps_across_stretch_edges_need_the_longer_watch_and_a_leak_fails_it_too() {
        // A 400 KB step spread over the three frames around the edge between
        // the third stretch and the fourth raises both, and one of 400 KB
        // inside the fifth raises that one: three of six is enough to move
        // the median.
        let edge = 100 + 3 * S;
        let steps =
            |f: u64| (f.clamp(edge - 1, edge + 1) - (edge - 1)) as f64 * 200e3 + if f > edge + S { 400e3 } else { 0.0 };
        let six = watched(|f| 300e6 + steps(f));
        let judged = growth_per_frame(&six).unwrap();
        assert!(judged > LEAK_BOUND, "the median of six: {judged}");
        let quiet = growth_per_frame(&watched_more(MORE_WATCHED_FRAMES, |f| 300e6 + steps(f))).unwrap();
        assert_eq!(quiet, 0.0, "twelve stretches, three raised");
        // A leak just over the bound, with the same steps, stays one.
        let leaking =
            growth_per_frame(&watched_more(MORE_WATCHED_FRAMES, |f| 300e6 + steps(f) + 8500.0 * (f - 100) as f64))
                .unwrap();
        assert!(leaking > LEAK_BOUND, "{leaking}");
    }

    #[test]
    fn readings_every_third_frame_need_the_longer_stretches() {
        // A page read every third frame from frame 100, once missing one
        // (frame 133): the five-frame stretch from 130 to 135 holds one
        // reading, and says nothing; every ten-frame one holds three or four.
        let span = STRETCHES as u64 * SPARSE_STRETCH_FRAMES;
        let sparse: Vec<Reading> =
            (0..=span / 3).map(|i| 100 + 3 * i).filter(|&f| f != 133).map(|f| (f, 5000 * (f - 100))).collect();
        assert_eq!(growth_per_frame_in(&sparse, STRETCH_FRAMES), None);
        assert_eq!(growth_per_frame_in(&sparse, SPARSE_STRETCH_FRAMES), Some(5000.0));
    }

    #[test]
    fn too_few_frames_say_nothing() {
        let short: Vec<Reading> = (0..WATCHED_FRAMES).map(|f| (f, 1000 * f)).collect();
        assert_eq!(growth_per_frame(&short), None, "one frame short of the watch");
        let mut enough = short.clone();
        enough.push((WATCHED_FRAMES, 1000 * WATCHED_FRAMES));
        assert_eq!(growth_per_frame(&enough), Some(1000.0));
        assert_eq!(growth_per_frame(&[]), None);
    }

    #[test]
    fn cycles_grow_by_their_median() {
        // A first resize fills a cache; a leak grows every cycle.
        assert_eq!(growth_per_cycle(&[100, 9_000_100, 9_000_300, 9_000_200]), Some(200.0));
        assert_eq!(growth_per_cycle(&[0, 3_000_000, 6_100_000, 9_000_000]), Some(3_000_000.0));
        assert_eq!(growth_per_cycle(&[5]), None);
    }
}
