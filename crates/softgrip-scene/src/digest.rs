//! [`ContactDigest`]: one number for every contact value of a run, bit for bit (the golden
//! digest that `softgrip run --digest` prints and a test holds against a committed value).

use std::fmt;

use softgrip_law::ContactReading;

const FNV_OFFSET: u64 = 0xcbf2_9ce4_8422_2325;
const FNV_PRIME: u64 = 0x0000_0100_0000_01b3;

/// A 64-bit FNV-1a hash of the bit patterns of every soft contact's values, step by step:
/// per step the number of contacts, then per contact (in the plugin's readout order) these
/// fields of its [`ContactReading`]: normal force, compression, x, torsional moment,
/// stiffness, peak normal force, friction force, point and normal (f64 bits, little-endian). Two runs have equal digests only if
/// every one of these values is bit-identical at every step (up to a hash collision).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct ContactDigest {
    hash: u64,
    steps: u64,
    contacts: u64,
}

impl Default for ContactDigest {
    fn default() -> Self {
        Self {
            hash: FNV_OFFSET,
            steps: 0,
            contacts: 0,
        }
    }
}

impl ContactDigest {
    /// The digest of no step.
    pub fn new() -> Self {
        Self::default()
    }

    /// Adds one step's contacts (the plugin's readout after the step, in its order: its
    /// `TipContact`s, or their [`ContactReading`]s).
    pub fn add_step<'a, C: AsRef<ContactReading> + 'a>(
        &mut self,
        contacts: impl ExactSizeIterator<Item = &'a C>,
    ) {
        self.steps += 1;
        self.word(contacts.len() as u64);
        for c in contacts {
            self.add_contact(c.as_ref());
        }
    }

    /// Adds one contact's values.
    fn add_contact(&mut self, c: &ContactReading) {
        self.contacts += 1;
        let scalars = [
            c.normal_force,
            c.delta,
            c.x,
            c.torsional_moment,
            c.stiffness,
            c.peak_normal_force,
        ];
        let vectors = [c.friction_force, c.point, c.normal];
        for v in scalars.into_iter().chain(vectors.into_iter().flatten()) {
            self.word(v.to_bits());
        }
    }

    fn word(&mut self, w: u64) {
        for byte in w.to_le_bytes() {
            self.hash = (self.hash ^ u64::from(byte)).wrapping_mul(FNV_PRIME);
        }
    }

    /// The hash so far.
    pub fn value(&self) -> u64 {
        self.hash
    }

    /// Steps added.
    pub fn steps(&self) -> u64 {
        self.steps
    }

    /// Contacts added, over all steps.
    pub fn contacts(&self) -> u64 {
        self.contacts
    }
}

impl fmt::Display for ContactDigest {
    /// `digest <16 hex digits> steps <n> contacts <m>`.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "digest {:016x} steps {} contacts {}",
            self.hash, self.steps, self.contacts
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn fnv1a_of_known_bytes() {
        // FNV-1a 64 of the 8 bytes of 0u64 (reference value of the algorithm).
        let mut d = ContactDigest::new();
        d.word(0);
        assert_eq!(d.value(), 0xa8c7_f832_281a_39c5);
    }
}
