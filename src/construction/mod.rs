//! Chapter 4: the PPM set of gluing data built from a simplicial surface (issue 4).
