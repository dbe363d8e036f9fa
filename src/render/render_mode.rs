//! How the water surface is drawn: ray-traced per pixel, as flat water (the games' technique,
//! `flat.rs`), or both split by a divider; and flat water's two choices, what shifts its
//! lookups and what lights the pool under it. The pool's renderer, its input (the divider),
//! the shader variants and the shells' costs per mode read them.

crate::choices! {
    /// How the water surface is drawn (the `render_mode` parameter).
    #[derive(Default)]
    pub enum RenderMode {
        #[default]
        RayTraced = "raytraced",
        Flat = "flat",
        /// Flat left of the divider, ray-traced right of it.
        Split = "split",
    }
}

crate::choices! {
    /// What shifts the flat water's texture lookups (the `flat_distortion` parameter).
    #[derive(Default)]
    pub enum Distortion {
        #[default]
        Dudv = "dudv",
        /// The simulated surface's slopes (and the ambient waves').
        Ripples = "ripples",
    }
}

crate::choices! {
    /// The light on the pool under flat water (the `flat_caustics` parameter).
    #[derive(Default)]
    pub enum FlatCaustics {
        Off = "off",
        /// A highlight from the distortion's normal (the games' fake caustics).
        #[default]
        Fake = "fake",
        /// The ray tracer's caustics map.
        Real = "real",
    }
}
