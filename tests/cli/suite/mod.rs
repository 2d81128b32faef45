//! The same paths as in the library's test binary (`suite::THEME::FILE::test`), so that one
//! filter (`cargo test suite::surface::`) selects a theme's tests in both binaries.

mod chapter4 {
    mod construction_mesh;
}
mod mesh {
    mod adversarial;
}
mod seeds {
    mod fitting;
    mod msplines;
    mod sdiff_3d;
    mod sdiff_spec;
}
mod surface {
    mod docs_pictures;
    mod one_surface;
    mod oracle;
    mod oracle_surface;
    mod python_layer;
    mod sigma_v;
}
