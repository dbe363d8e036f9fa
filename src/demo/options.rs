//! The choices fixed when the demo is created, and their specs (the one source of their
//! names, ranges and defaults for the web options, the URL and the command line).

use crate::params::ParamId;

/// Choices fixed when the demo is created.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct DemoOptions {
    /// Simulation cells per side at the start (a power of two); the `sim_size` parameter
    /// starts at the nearest of its choices and changes it later.
    pub sim_size: u32,
    /// Caustics map texels per side.
    pub caustics_size: u32,
    /// Quads per side of the water surface mesh. Software rasterisers pay mostly per
    /// triangle, and the surface is shaded per pixel anyway: 48 costs little detail.
    pub surface_grid: u32,
    /// Whether the device can render into float textures. Without, the water is simulated
    /// by the CPU reference and the caustics map is 8-bit; the picture stays the same.
    pub float_targets: bool,
}

/// One creation option as the shells show it (web mount options and URL, CLI flags): its
/// name, range and default; any integer in the range is allowed.
#[derive(Clone, Copy, Debug)]
pub struct OptionSpec {
    pub name: &'static str,
    pub label: &'static str,
    pub min: u32,
    pub max: u32,
    pub default: u32,
}

impl OptionSpec {
    /// `value` clamped to the range.
    pub fn clamp(&self, value: u32) -> u32 {
        value.clamp(self.min, self.max)
    }
}

impl DemoOptions {
    /// The creation options' table: the one source of their names, ranges and defaults.
    pub const SPECS: [OptionSpec; 2] = [
        OptionSpec {
            name: "meshSize",
            label: "quads per side of the water surface mesh",
            min: 16,
            max: 512,
            default: 48,
        },
        OptionSpec {
            name: "causticsSize",
            label: "texels per side of the caustics map",
            min: 128,
            max: 2048,
            default: 512,
        },
    ];

    /// Options from raw values: the simulation size as the `sim_size` parameter would take it,
    /// mesh and caustics sizes clamped to their specs.
    pub fn clamped(sim_size: u32, surface_grid: u32, caustics_size: u32) -> Self {
        let [mesh, caustics] = &Self::SPECS;
        Self {
            sim_size: crate::params::spec(ParamId::SimSize).sanitise(sim_size as f32) as u32,
            surface_grid: mesh.clamp(surface_grid),
            caustics_size: caustics.clamp(caustics_size),
            float_targets: true,
        }
    }
}

impl Default for DemoOptions {
    fn default() -> Self {
        let [mesh, caustics] = &Self::SPECS;
        Self {
            sim_size: crate::params::spec(ParamId::SimSize).default as u32,
            surface_grid: mesh.default,
            caustics_size: caustics.default,
            float_targets: true,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    pub(super) fn creation_options_clamp_and_snap_to_their_specs() {
        assert_eq!(
            DemoOptions::clamped(300, 4, 99_999),
            DemoOptions { sim_size: 256, surface_grid: 16, caustics_size: 2048, float_targets: true }
        );
        assert_eq!(DemoOptions::clamped(5000, 100, 700).sim_size, 1024);
        assert_eq!(DemoOptions::clamped(0, 100, 700).sim_size, 128);
        let d = DemoOptions::default();
        assert_eq!(DemoOptions::clamped(d.sim_size, d.surface_grid, d.caustics_size), d, "defaults lie in range");
    }
}
