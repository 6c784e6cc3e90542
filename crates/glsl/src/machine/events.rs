//! What a run reports: the events of the traced lane, statement by statement, and the failure
//! that stops a run, each at its place in the student's source.

/// A failure of one run, at its place in the student's source (bytes).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct RunError {
    /// Where (bytes of the student's source).
    pub at: usize,
    /// What happened, as a sentence (English).
    pub message: String,
    /// What happened, as data, for the interface to say in its language.
    pub complaint: crate::complaint::Complaint,
}

/// What the traced lane did at one statement. `at` is always the statement's place in the
/// student's source (bytes).
#[derive(Clone, Debug, PartialEq)]
pub enum Event {
    /// A variable was written.
    Assign {
        /// Where.
        at: usize,
        /// The variable's name.
        name: String,
        /// Its type.
        ty: naga::Handle<naga::Type>,
        /// Its whole new value.
        bits: Vec<u32>,
    },
    /// An `if`.
    Branch {
        /// Where.
        at: usize,
        /// Whether its condition held.
        taken: bool,
    },
    /// A loop tested its condition (`for`'s or `while`'s).
    LoopTest {
        /// Where (the loop's line).
        at: usize,
        /// Whether the condition held (another iteration).
        holds: bool,
    },
    /// A `break` the student wrote.
    Break {
        /// Where.
        at: usize,
    },
    /// A `continue`.
    Continue {
        /// Where.
        at: usize,
    },
    /// A loop began an iteration.
    Iteration {
        /// Where.
        at: usize,
        /// Which, from 1.
        k: u32,
    },
    /// A function was called.
    Call {
        /// Where.
        at: usize,
        /// The function.
        name: String,
    },
    /// A function returned (not the entry point).
    Return {
        /// Where.
        at: usize,
        /// The function.
        name: String,
        /// What it returned, with its type (none for a `void` function).
        value: Option<(naga::Handle<naga::Type>, Vec<u32>)>,
    },
    /// The fragment was discarded.
    Discard {
        /// Where.
        at: usize,
    },
}
