//! What an instance did since its world was built: the inputs it handed to the driver at each
//! communication point and how many basic steps it ran with them. The engine is deterministic
//! (the same world and commands give the same run bit for bit, `fmu/tests/fmi2.rs`), so the
//! journal *is* the state in a form that outlives the process: a serialised FMU state is the
//! world's identity, the parameters and the journal, and restoring it replays the journal in a
//! freshly built world.
//!
//! Why a replay rather than the bodies' bytes: the engine's snapshot holds rapier's sets,
//! islands and contact caches, which serialise only with rapier's serde feature (off in this
//! workspace, and a format tied to rapier's version); a journal is a few dozen bytes per input
//! change, stable across rapier versions, and restores the exact state. Its cost is the replay:
//! restoring a state at time t runs the world from 0 to t (at the engine's speed, hundreds of
//! times real time).
//!
//! The journal is a linked list of shared links so that taking a state (once per step, for a
//! model-predictive controller) costs O(1) and states saved on diverging branches share their
//! common past.

use std::sync::Arc;

/// The number of inputs (value references 0 to 6).
pub const INPUTS: usize = 7;

/// A stretch of the run: the inputs handed over at its start and the basic steps run with them.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Stretch {
    /// The inputs, by value reference (integers stored as f64 exactly).
    pub inputs: [f64; INPUTS],
    /// Basic steps run with them.
    pub steps: u64,
}

/// The stretches since the world was built, newest first; cheap to clone.
#[derive(Debug, Clone, Default)]
pub struct Journal(Option<Arc<Link>>);

#[derive(Debug)]
struct Link {
    stretch: Stretch,
    earlier: Journal,
}

impl Journal {
    /// `steps` basic steps run after `inputs` were handed over: a new stretch, or the newest
    /// one lengthened when the inputs are the same bits (the driver then received nothing, so
    /// one stretch replays both).
    pub fn push(&mut self, inputs: [f64; INPUTS], steps: u64) {
        let same = |a: &[f64; INPUTS]| {
            a.iter()
                .zip(&inputs)
                .all(|(x, y)| x.to_bits() == y.to_bits())
        };
        if let Some(head) = &self.0
            && same(&head.stretch.inputs)
        {
            let merged = Stretch {
                inputs,
                steps: head.stretch.steps + steps,
            };
            let earlier = head.earlier.clone();
            self.0 = Some(Arc::new(Link {
                stretch: merged,
                earlier,
            }));
            return;
        }
        let earlier = std::mem::take(self);
        self.0 = Some(Arc::new(Link {
            stretch: Stretch { inputs, steps },
            earlier,
        }));
    }

    /// The stretches, oldest first.
    pub fn stretches(&self) -> Vec<Stretch> {
        let mut out = Vec::new();
        let mut link = self.0.as_deref();
        while let Some(l) = link {
            out.push(l.stretch);
            link = l.earlier.0.as_deref();
        }
        out.reverse();
        out
    }

    /// The journal of `stretches`, oldest first.
    pub fn from_stretches(stretches: &[Stretch]) -> Journal {
        let mut journal = Journal::default();
        for s in stretches {
            let earlier = std::mem::take(&mut journal);
            journal.0 = Some(Arc::new(Link {
                stretch: *s,
                earlier,
            }));
        }
        journal
    }
}

impl Drop for Journal {
    /// Unlinks iteratively: a journal of a million stretches would overflow the stack if each
    /// link dropped the next recursively.
    fn drop(&mut self) {
        let mut next = self.0.take();
        while let Some(link) = next {
            match Arc::try_unwrap(link) {
                Ok(mut owned) => next = owned.earlier.0.take(),
                Err(_) => break,
            }
        }
    }
}

/// The magic bytes and format version at the start of a serialised state.
const MAGIC: &[u8; 12] = b"vehicle-fmu\x01";

/// A state in a form another instance (of the same FMU, in this or another process) can load.
#[derive(Debug, Clone, PartialEq)]
pub struct Serialised {
    /// The FMU's GUID / instantiation token.
    pub guid: String,
    /// A fingerprint of the world file's text.
    pub world: u64,
    /// The phase, as [`crate::instance::Phase`]'s index.
    pub phase: u8,
    /// The inputs as last set.
    pub inputs: [f64; INPUTS],
    /// The inputs the driver last received.
    pub applied: Option<[f64; INPUTS]>,
    /// The parameters set, by value reference.
    pub parameters: Vec<(u32, f64)>,
    /// The run since the world was built.
    pub stretches: Vec<Stretch>,
}

/// FNV-1a (64 bit) of `bytes`: a fingerprint to tell worlds apart, not a secret.
pub fn fingerprint(bytes: &[u8]) -> u64 {
    bytes.iter().fold(0xcbf2_9ce4_8422_2325, |h, b| {
        (h ^ u64::from(*b)).wrapping_mul(0x0000_0100_0000_01b3)
    })
}

impl Serialised {
    /// The bytes: little-endian, lengths as u64.
    pub fn to_bytes(&self) -> Vec<u8> {
        let mut b = Vec::with_capacity(128 + self.stretches.len() * 64);
        b.extend_from_slice(MAGIC);
        b.extend_from_slice(&(self.guid.len() as u64).to_le_bytes());
        b.extend_from_slice(self.guid.as_bytes());
        b.extend_from_slice(&self.world.to_le_bytes());
        b.push(self.phase);
        let floats = |b: &mut Vec<u8>, values: &[f64; INPUTS]| {
            for v in values {
                b.extend_from_slice(&v.to_bits().to_le_bytes());
            }
        };
        floats(&mut b, &self.inputs);
        match &self.applied {
            Some(applied) => {
                b.push(1);
                floats(&mut b, applied);
            }
            None => b.push(0),
        }
        b.extend_from_slice(&(self.parameters.len() as u64).to_le_bytes());
        for (reference, value) in &self.parameters {
            b.extend_from_slice(&reference.to_le_bytes());
            b.extend_from_slice(&value.to_bits().to_le_bytes());
        }
        b.extend_from_slice(&(self.stretches.len() as u64).to_le_bytes());
        for s in &self.stretches {
            floats(&mut b, &s.inputs);
            b.extend_from_slice(&s.steps.to_le_bytes());
        }
        b
    }

    /// Reads what [`Serialised::to_bytes`] wrote.
    ///
    /// # Errors
    /// Bytes that are not a state of this format (truncated, another format or version, a
    /// count larger than the bytes could hold), as a sentence.
    pub fn from_bytes(bytes: &[u8]) -> Result<Serialised, String> {
        let mut r = Reader { bytes, at: 0 };
        if r.take(MAGIC.len())? != MAGIC {
            return Err("these bytes are not a serialised state of this FMU's format".into());
        }
        let guid_len = r.count(1)?;
        let guid = String::from_utf8(r.take(guid_len)?.to_vec())
            .map_err(|_| "the state's GUID is not UTF-8".to_string())?;
        let world = r.u64()?;
        let phase = r.take(1)?[0];
        let inputs = r.floats()?;
        let applied = match r.take(1)?[0] {
            0 => None,
            1 => Some(r.floats()?),
            other => return Err(format!("bad applied-inputs flag {other} in the state")),
        };
        let n = r.count(12)?;
        let mut parameters = Vec::with_capacity(n);
        for _ in 0..n {
            let reference = u32::from_le_bytes(r.array()?);
            parameters.push((reference, f64::from_bits(r.u64()?)));
        }
        let n = r.count(8 * INPUTS + 8)?;
        let mut stretches = Vec::with_capacity(n);
        for _ in 0..n {
            let inputs = r.floats()?;
            stretches.push(Stretch {
                inputs,
                steps: r.u64()?,
            });
        }
        if r.at != bytes.len() {
            return Err(format!(
                "{} bytes after the end of the serialised state",
                bytes.len() - r.at
            ));
        }
        Ok(Serialised {
            guid,
            world,
            phase,
            inputs,
            applied,
            parameters,
            stretches,
        })
    }
}

/// A cursor over serialised bytes.
struct Reader<'a> {
    bytes: &'a [u8],
    at: usize,
}

impl<'a> Reader<'a> {
    fn take(&mut self, n: usize) -> Result<&'a [u8], String> {
        let end = self.at.checked_add(n).filter(|&e| e <= self.bytes.len());
        let Some(end) = end else {
            return Err(format!(
                "the serialised state is truncated at byte {} of {}",
                self.at,
                self.bytes.len()
            ));
        };
        let out = &self.bytes[self.at..end];
        self.at = end;
        Ok(out)
    }

    fn array<const N: usize>(&mut self) -> Result<[u8; N], String> {
        let mut out = [0; N];
        out.copy_from_slice(self.take(N)?);
        Ok(out)
    }

    fn u64(&mut self) -> Result<u64, String> {
        Ok(u64::from_le_bytes(self.array()?))
    }

    /// A count of items of at least `size` bytes each, refused when the rest cannot hold them.
    fn count(&mut self, size: usize) -> Result<usize, String> {
        let n = self.u64()?;
        let rest = (self.bytes.len() - self.at) as u64;
        if n.saturating_mul(size as u64) > rest {
            return Err(format!(
                "the serialised state counts {n} items where {rest} bytes remain"
            ));
        }
        Ok(n as usize)
    }

    fn floats(&mut self) -> Result<[f64; INPUTS], String> {
        let mut out = [0.0; INPUTS];
        for v in &mut out {
            *v = f64::from_bits(self.u64()?);
        }
        Ok(out)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn equal_inputs_lengthen_the_newest_stretch_and_states_share_their_past() {
        let a = [1.0, 0.0, 0.0, 0.0, 1.0, 1.0, 0.0];
        let b = [0.0, 0.5, 0.0, 0.0, 1.0, 1.0, 0.0];
        let mut j = Journal::default();
        j.push(a, 5);
        j.push(a, 5);
        let saved = j.clone();
        j.push(b, 3);
        assert_eq!(
            j.stretches(),
            vec![
                Stretch {
                    inputs: a,
                    steps: 10
                },
                Stretch {
                    inputs: b,
                    steps: 3
                }
            ]
        );
        assert_eq!(
            saved.stretches(),
            vec![Stretch {
                inputs: a,
                steps: 10
            }]
        );
        // -0.0 and 0.0 are different bits: a different input the driver received.
        let mut c = a;
        c[1] = -0.0;
        j.push(c, 1);
        assert_eq!(j.stretches().len(), 3);
    }

    #[test]
    fn a_long_journal_drops_without_recursion() {
        let mut j = Journal::default();
        for k in 0..1_000_000 {
            j.push([f64::from(k % 2), 0.0, 0.0, 0.0, 1.0, 1.0, 0.0], 1);
        }
        assert_eq!(j.stretches().len(), 1_000_000);
        drop(j);
    }

    #[test]
    fn serialised_states_round_trip_and_damaged_bytes_are_refused() {
        let s = Serialised {
            guid: "{abc}".into(),
            world: fingerprint(b"basicTimeStep = 10"),
            phase: 2,
            inputs: [0.1, 1.0, 0.0, 20.0, 1.0, 2.0, 0.0],
            applied: Some([0.1, 1.0, 0.0, 20.0, 1.0, 2.0, 0.0]),
            parameters: vec![(1000, 1500.0)],
            stretches: vec![Stretch {
                inputs: [0.0; INPUTS],
                steps: 42,
            }],
        };
        let bytes = s.to_bytes();
        assert_eq!(Serialised::from_bytes(&bytes), Ok(s));
        for cut in [0, 5, 20, bytes.len() - 1] {
            assert!(
                Serialised::from_bytes(&bytes[..cut]).is_err(),
                "cut at {cut}"
            );
        }
        let mut longer = bytes.clone();
        longer.push(0);
        assert!(Serialised::from_bytes(&longer).is_err());
        // A count far beyond the bytes is refused before anything is allocated for it.
        let mut huge = bytes;
        let at = MAGIC.len();
        huge[at..at + 8].copy_from_slice(&u64::MAX.to_le_bytes());
        assert!(Serialised::from_bytes(&huge).is_err());
    }
}
