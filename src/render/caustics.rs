//! The caustics map every scene pass binds, and its mip chain: the water grid projected along
//! the refracted sunlight, each triangle adding the light its area gathers (drawn by the pool's
//! caustics pass, `scenes/pool/render/caustics.rs`).

use super::caustics_mips::CausticsMips;
use super::Renderer;
use crate::param_spec::{Control, ParamSpec};

/// Caustics map: red = light, green = light with the sphere's shadow.
pub const CAUSTICS_FORMAT: wgpu::TextureFormat = wgpu::TextureFormat::Rg16Float;
/// Caustics map where float render targets are missing: 8-bit, holding light / [`CAUSTICS_8BIT_SCALE`].
pub const CAUSTICS_FORMAT_8BIT: wgpu::TextureFormat = wgpu::TextureFormat::Rg8Unorm;
/// Light (relative to a calm surface) that the 8-bit caustics map's 1.0 stands for: focused
/// light up to 10x is kept in 1/255 steps of it, brighter lines are clipped (the tone curve
/// has flattened them by then anyway).
pub const CAUSTICS_8BIT_SCALE: f32 = 10.0;
/// The caustics map (the scene passes read it; the pool's caustics pass draws the water grid into
/// it).
pub(super) struct CausticsMap {
    /// The map and its mip chain.
    pub(super) mips: CausticsMips,
    /// Texels per side.
    pub(super) size: u32,
    /// Whether `view` holds light per colour channel (dispersion; an RGBA map).
    pub(super) per_channel: bool,
}

impl CausticsMap {
    pub(super) fn new(device: &wgpu::Device, size: u32, format: wgpu::TextureFormat) -> Self {
        Self { mips: CausticsMips::new(device, size, format), size, per_channel: false }
    }
}

impl Renderer {
    /// Side (texels) of the caustics map for a frame drawn at `render_scale`: the map's texels
    /// follow the screen's pixels, so a frame at half resolution also lights the pool from a
    /// map of half the side (at least 128), a quarter of the work.
    pub fn caustics_size(&self, render_scale: f32) -> u32 {
        let side = (self.settings.caustics_size as f32 * render_scale.clamp(0.25, 1.0)).round() as u32;
        side.clamp(128.min(self.settings.caustics_size), self.settings.caustics_size)
    }

    /// Makes the caustics map `size` texels per side, with light per colour channel or not
    /// (rebinding it), if it is not already.
    pub fn resize_caustics(&mut self, device: &wgpu::Device, size: u32, per_channel: bool) {
        if size != self.caustics.size || per_channel != self.caustics.per_channel {
            self.caustics.mips = CausticsMips::new(device, size, self.settings.caustics_format_for(per_channel).0);
            self.caustics.size = size;
            self.caustics.per_channel = per_channel;
            self.textures_group =
                self.scene_textures.bind_group(device, &self.textures_layout, &self.caustics.mips.view);
        }
    }

    /// The caustics map's finest level, to draw into (then [`Renderer::encode_caustics_mips`]).
    pub fn caustics_target(&self) -> &wgpu::TextureView {
        &self.caustics.mips.target
    }

    /// Makes the caustics map's coarser levels from its finest.
    pub fn encode_caustics_mips(&self, encoder: &mut wgpu::CommandEncoder) {
        self.caustics.mips.encode(encoder);
    }
}

/// Caustics on or off, and how much their lines stand out. (The parameter table,
/// `params::table`, lists them in this order.)
///
/// The contrast is a power the map's light is raised to where the scene is lit by it (calm
/// water's 1 stays 1, a shadow's 0 stays 0; the map holds the rim's and the bodies' shadows, so
/// their half-lit edges are raised too and the penumbras narrow a little). The sun's disc is
/// half a degree, so a real caustic line a metre down is a few millimetres wide and many times
/// calm water's light; the map, drawn from a grid of centimetre triangles and read over each
/// pixel's footprint, spreads it over two or three texels at a fraction of that, and the tone
/// curve's shoulder squeezes what is left. Squaring gives the lines back their punch: the
/// default view's net reads as the net of a sunlit pool (judged blind against 1, 2026-11-29).
/// A power of 3 was judged slightly better still (2026-11-30), but its thinner lines lift the
/// page's sparkle share over the classic's (1.48 % against 1.10 %; docs/PERFORMANCE.md).
pub const PARAMS: &[ParamSpec] = &[
    ParamSpec {
        name: "caustics",
        label: "Caustics",
        group: "Light",
        unit: "",
        control: Control::Toggle,
        default: 1.0,
        help: "Light focused by the waves onto the floor, walls and sphere.",
    },
    ParamSpec {
        name: "caustic_contrast",
        label: "Caustic contrast",
        group: "Light",
        unit: "",
        control: Control::Slider { min: 1.0, max: 3.0, step: 0.1 },
        default: 2.0,
        help: "How much the caustic lines stand out: the focused light raised to this power. 1 is the light the simulated waves focus, as the caustics map holds it (blurred over its texels, so the lines are wider and dimmer than the sun would draw them); 2 gives them back the brightness of a sunlit pool's net.",
    },
];
