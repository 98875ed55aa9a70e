//! Saving and restoring an instance (`GetFMUstate`, `SetFMUstate`, `SerializeFMUstate`,
//! `DeSerializeFMUstate`): the engine's snapshot where it can, else the journal replayed.

use sim::traffic::TrafficPosition;

use super::{Instance, Phase, Refused, Severity};
use crate::journal::{self, INPUTS, Journal, Serialised};
use crate::model_description::guid;

/// A saved instance state (`fmi2FMUstate`, `fmi3FMUState`): the world's snapshot (absent in a
/// state read from bytes), the journal that rebuilds it anywhere, and the inputs, parameters
/// and phase around it.
#[derive(Clone)]
pub struct State {
    snapshot: Option<sim::Snapshot>,
    traffic: TrafficPosition,
    world: u64,
    phase: Phase,
    inputs: [f64; INPUTS],
    applied: Option<[f64; INPUTS]>,
    parameters: Vec<(u32, f64)>,
    journal: Journal,
}

impl Instance {
    /// `GetFMUstate`: everything a later [`Instance::set_state`] needs to continue exactly as
    /// this instance would from here.
    pub fn state(&self) -> State {
        State {
            snapshot: Some(self.world.simulation.snapshot()),
            traffic: self.world.traffic.position(),
            world: journal::fingerprint(self.world_text.as_bytes()),
            phase: self.phase,
            inputs: self.inputs,
            applied: self.applied,
            parameters: self.parameters.clone(),
            journal: self.journal.clone(),
        }
    }

    /// `SetFMUstate`: back to `state`. A state this instance saved since its world was last
    /// built comes back from the engine's snapshot; any other state of the same world (saved
    /// by another instance, before a reset, or read from bytes) is rebuilt by replaying its
    /// journal in a fresh world, which gives the same bits (the engine is deterministic).
    ///
    /// # Errors
    /// A state of another world (nothing changes), or a world that can no longer be built.
    pub fn set_state(&mut self, state: &State) -> Result<(), Refused> {
        let function = self.version.name("SetFMUState");
        if state.world != journal::fingerprint(self.world_text.as_bytes()) {
            return Err(self.refuse(format!(
                "{function}: the state is of another world than this instance's {}",
                self.world_path.display()
            )));
        }
        self.telemetry = None;
        let restored = state
            .snapshot
            .as_ref()
            .is_some_and(|snap| self.world.simulation.restore(snap).is_ok());
        if restored {
            self.world.traffic.set_position(&state.traffic);
        } else if let Err(e) = self.replay(state) {
            return Err(self.refuse(format!("{function}: {e}")));
        }
        self.phase = state.phase;
        self.inputs = state.inputs;
        self.applied = state.applied;
        self.parameters.clone_from(&state.parameters);
        self.journal = state.journal.clone();
        Ok(())
    }

    /// Rebuilds the world of `state` (with its parameters once initialised) and replays its
    /// journal, discarding the driver's warnings (they were logged when the run was first made).
    fn replay(&mut self, state: &State) -> Result<(), Refused> {
        let initialised = matches!(state.phase, Phase::Stepping | Phase::Terminated);
        let parameters = if initialised {
            state.parameters.as_slice()
        } else {
            &[]
        };
        self.world = self.rebuild(parameters)?;
        self.applied = None;
        for stretch in state.journal.stretches() {
            self.inputs = stretch.inputs;
            self.apply_inputs();
            self.run(stretch.steps)?;
        }
        self.messages
            .retain(|(severity, _)| *severity == Severity::Error);
        Ok(())
    }

    /// The bytes of `state` (`SerializeFMUstate`), loadable by any instance of this FMU with
    /// the same world.
    pub fn serialise(state: &State) -> Vec<u8> {
        Serialised {
            guid: guid(),
            world: state.world,
            phase: Phase::ALL
                .iter()
                .position(|p| *p == state.phase)
                .unwrap_or(0) as u8,
            inputs: state.inputs,
            applied: state.applied,
            parameters: state.parameters.clone(),
            stretches: state.journal.stretches(),
        }
        .to_bytes()
    }

    /// The state in `bytes` (`DeSerializeFMUstate`); it is checked against this instance's
    /// world when set.
    ///
    /// # Errors
    /// Bytes that are not a state of this FMU (another format, another build, damaged).
    pub fn deserialise(&mut self, bytes: &[u8]) -> Result<State, Refused> {
        let function = self.version.name("DeserializeFMUState");
        let s = match Serialised::from_bytes(bytes) {
            Ok(s) => s,
            Err(e) => return Err(self.refuse(format!("{function}: {e}"))),
        };
        if s.guid != guid() {
            return Err(self.refuse(format!(
                "{function}: the state was saved by another build of the FMU (GUID {}, this \
                 one {})",
                s.guid,
                guid()
            )));
        }
        let Some(&phase) = Phase::ALL.get(usize::from(s.phase)) else {
            return Err(self.refuse(format!("{function}: unknown phase {}", s.phase)));
        };
        if !s.inputs.iter().all(|v| v.is_finite())
            || !s.parameters.iter().all(|(_, v)| v.is_finite())
        {
            return Err(self.refuse(format!("{function}: the state holds a non-finite value")));
        }
        Ok(State {
            snapshot: None,
            // The replay brings the traffic to its place.
            traffic: self.world.traffic.position(),
            world: s.world,
            phase,
            inputs: s.inputs,
            applied: s.applied,
            parameters: s.parameters,
            journal: Journal::from_stretches(&s.stretches),
        })
    }
}
