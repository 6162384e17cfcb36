//! `Gpu::cached` makes a value once per key and type, and keeps one per type.

use std::cell::Cell;
use std::sync::Arc;

use common::{Gpu, GpuNeeds};

#[test]
fn values_are_made_once_per_key_and_replaced_by_another_key() {
    let gpu = Gpu::headless(GpuNeeds::default()).expect("an adapter (lavapipe will do)");
    let made = Cell::new(0);
    let make = |text: &str| {
        made.set(made.get() + 1);
        text.to_string()
    };
    let first = gpu.cached(1u32, || make("one"));
    let again = gpu.cached(1u32, || make("not made"));
    assert!(Arc::ptr_eq(&first, &again) && made.get() == 1, "the same key gives the same value, made once");
    let other = gpu.cached(2u32, || make("two"));
    assert_eq!((other.as_str(), made.get()), ("two", 2));
    // One value is kept per type: key 1 is made again, and `first` lives on with its holder.
    let back = gpu.cached(1u32, || make("one again"));
    assert_eq!((back.as_str(), first.as_str(), made.get()), ("one again", "one", 3));
    // Values of another type have their own slot.
    let number = gpu.cached(1u32, || 7u64);
    assert_eq!(*number, 7);
    assert_eq!(gpu.cached(1u32, || make("unused")).as_str(), "one again");
}
