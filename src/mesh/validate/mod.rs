//! The named checks of Sec. 3.1. Being written in issue 2.
