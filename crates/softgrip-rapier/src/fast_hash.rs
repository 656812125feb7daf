//! Hash maps and sets keyed by rapier handles (plain integers: an index and a generation),
//! hashed with `rustc-hash`'s Fx hasher instead of the standard library's SipHash: a step looks
//! up every fingertip, contact and body in them, and SipHash's keyed rounds were a tenth of a
//! resting fingertip's step. No key comes from outside the process (handles are rapier's), so
//! SipHash's resistance to chosen keys buys nothing here. Nothing iterates these maps in an
//! order that reaches the results (the standard hasher's order was random per process).

/// A hash map with the Fx hasher (`FastMap::default()` makes an empty one).
pub(crate) type FastMap<K, V> = std::collections::HashMap<K, V, rustc_hash::FxBuildHasher>;

/// A hash set with the Fx hasher.
pub(crate) type FastSet<K> = std::collections::HashSet<K, rustc_hash::FxBuildHasher>;
