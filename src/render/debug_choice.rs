//! What the debug view shows: the `debug_view` parameter's options, the inner texture and
//! where it goes (the pool's passes draw it: `scenes/pool/render/debug_view.rs`).

/// Which inner texture the debug view shows (see `shaders/pool/debug_view.wgsl`), and where.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct DebugView {
    pub texture: DebugTexture,
    /// In the lower right corner (a square of 40% of the shorter side) instead of the whole target.
    pub inset: bool,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum DebugTexture {
    Height = 1,
    Normals = 2,
    Velocity = 3,
    Caustics = 4,
    /// The ambient waves' spectrum (not a simulation texture: `AmbientWaves::spectrum_image`).
    Spectrum = 6,
}

crate::choices! {
    /// What the `debug_view` parameter shows: nothing, one of the inner textures, or the
    /// water's Fresnel reflectance (not a texture but a variant of the surface shader,
    /// [`Optics::show_reflectance`]).
    pub enum DebugChoice {
        Off = "off",
        Height = "height",
        Normals = "normals",
        Velocity = "velocity",
        Caustics = "caustics",
        Reflectance = "reflectance",
        Spectrum = "spectrum",
    }
}

impl DebugChoice {
    /// The inner texture it shows, if any.
    pub fn texture(self) -> Option<DebugTexture> {
        match self {
            DebugChoice::Height => Some(DebugTexture::Height),
            DebugChoice::Normals => Some(DebugTexture::Normals),
            DebugChoice::Velocity => Some(DebugTexture::Velocity),
            DebugChoice::Caustics => Some(DebugTexture::Caustics),
            DebugChoice::Spectrum => Some(DebugTexture::Spectrum),
            DebugChoice::Off | DebugChoice::Reflectance => None,
        }
    }
}

impl DebugView {
    /// Viewport (x, y, width, height in pixels) of the view in a target of `size` pixels.
    pub fn viewport(&self, size: (u32, u32)) -> [f32; 4] {
        let (w, h) = (size.0 as f32, size.1 as f32);
        if !self.inset {
            // The largest centred square: the pool's square stays square.
            let side = w.min(h);
            return [(w - side) / 2.0, (h - side) / 2.0, side, side];
        }
        let side = (0.4 * w.min(h)).floor();
        let margin = (0.02 * w.min(h)).floor();
        [w - side - margin, h - side - margin, side, side]
    }
}
