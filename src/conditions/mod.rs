//! Conformance checkers: each statement of SPEC.md that is checked on data has its checker here
//! or in the module of the concept it checks, and reports through [`crate::report`].
