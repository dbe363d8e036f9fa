//! The scene passes' bind groups and what they bind: the uniforms with the water's state and
//! the ambient maps (group 0), the textures and samplers (group 1), the depth buffer.

use super::flat;
use super::{Renderer, DEPTH_FORMAT};
use crate::ambient::SPECTRUM_IMAGE_SIZE;
use crate::gpu;
use crate::sim::foam::Foam;
use crate::sim::HeightField;
use crate::textures::{self, SkyCube};

/// The textures and samplers of the scene passes' group 1, besides the caustics map.
pub(super) struct SceneTextures {
    pub(super) tiles: wgpu::TextureView,
    pub(super) sky: wgpu::TextureView,
    pub(super) fresnel_table: wgpu::TextureView,
    /// The foam amount per cell (R32Float), 1 x 1 until foam is first drawn.
    pub(super) foam: (wgpu::Texture, wgpu::TextureView),
    /// The ambient waves' spectrum for the debug view (R32Float, log10 of the amplitude in m).
    pub(super) spectrum: (wgpu::Texture, wgpu::TextureView),
    /// The flat water's dUdV map (flat.rs).
    pub(super) dudv: wgpu::TextureView,
    pub(super) clamp: wgpu::Sampler,
    pub(super) repeat: wgpu::Sampler,
}

impl SceneTextures {
    /// The tiles, sky cube, Fresnel table, a 1 x 1 foam map until foam is on, the spectrum
    /// image, the flat water's du/dv map and the two samplers; `tile_mips` from
    /// [`textures::tile_mips`].
    pub(super) fn new(device: &wgpu::Device, queue: &wgpu::Queue, sky_cube: &SkyCube, tile_mips: &[Vec<u8>]) -> Self {
        let tiles = textures::create_tile_texture(device, queue, tile_mips);
        let sampler = |address: wgpu::AddressMode| {
            device.create_sampler(&wgpu::SamplerDescriptor {
                address_mode_u: address,
                address_mode_v: address,
                address_mode_w: address,
                mag_filter: wgpu::FilterMode::Linear,
                min_filter: wgpu::FilterMode::Linear,
                // Nearest mip level for the repeating tiles: the level is chosen per pixel
                // already (tile_lod), and trilinear filtering costs software rasterisers twice
                // the texel reads. Linear for the clamped maps: the caustics map is read
                // between its levels (caustics_under), the others have one level.
                mipmap_filter: if address == wgpu::AddressMode::Repeat {
                    wgpu::MipmapFilterMode::Nearest
                } else {
                    wgpu::MipmapFilterMode::Linear
                },
                ..Default::default()
            })
        };
        SceneTextures {
            tiles: tiles.create_view(&Default::default()),
            sky: sky_cube.view(),
            fresnel_table: textures::create_fresnel_table(device, queue).create_view(&Default::default()),
            foam: foam_map(device, 1),
            spectrum: {
                let size = SPECTRUM_IMAGE_SIZE as u32;
                let usage = wgpu::TextureUsages::TEXTURE_BINDING | wgpu::TextureUsages::COPY_DST;
                let texture = gpu::texture_2d(
                    device,
                    "ambient spectrum",
                    (size, size, 1),
                    1,
                    wgpu::TextureFormat::R32Float,
                    usage,
                );
                let view = texture.create_view(&Default::default());
                (texture, view)
            },
            dudv: flat::dudv_texture(device, queue),
            clamp: sampler(wgpu::AddressMode::ClampToEdge),
            repeat: sampler(wgpu::AddressMode::Repeat),
        }
    }

    pub(super) fn bind_group(
        &self,
        device: &wgpu::Device,
        layout: &wgpu::BindGroupLayout,
        caustics: &wgpu::TextureView,
    ) -> wgpu::BindGroup {
        device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: Some("scene textures"),
            layout,
            entries: &[
                wgpu::BindGroupEntry { binding: 0, resource: wgpu::BindingResource::TextureView(caustics) },
                wgpu::BindGroupEntry { binding: 1, resource: wgpu::BindingResource::TextureView(&self.tiles) },
                wgpu::BindGroupEntry { binding: 2, resource: wgpu::BindingResource::TextureView(&self.sky) },
                wgpu::BindGroupEntry { binding: 3, resource: wgpu::BindingResource::Sampler(&self.clamp) },
                wgpu::BindGroupEntry { binding: 4, resource: wgpu::BindingResource::Sampler(&self.repeat) },
                wgpu::BindGroupEntry { binding: 5, resource: wgpu::BindingResource::TextureView(&self.fresnel_table) },
                wgpu::BindGroupEntry { binding: 6, resource: wgpu::BindingResource::TextureView(&self.foam.1) },
                wgpu::BindGroupEntry { binding: 7, resource: wgpu::BindingResource::TextureView(&self.spectrum.1) },
                wgpu::BindGroupEntry { binding: 8, resource: wgpu::BindingResource::TextureView(&self.dudv) },
            ],
        })
    }
}

/// A `size` x `size` foam map (R32Float, filled from the CPU).
pub(super) fn foam_map(device: &wgpu::Device, size: u32) -> (wgpu::Texture, wgpu::TextureView) {
    let usage = wgpu::TextureUsages::TEXTURE_BINDING | wgpu::TextureUsages::COPY_DST;
    let texture = gpu::texture_2d(device, "foam", (size, size, 1), 1, wgpu::TextureFormat::R32Float, usage);
    let view = texture.create_view(&Default::default());
    (texture, view)
}

/// The scene uniforms with each of the water's two state textures and the ambient map (group
/// 0 of every scene pass).
pub fn water_bind_groups(
    device: &wgpu::Device,
    layout: &wgpu::BindGroupLayout,
    uniforms: &wgpu::Buffer,
    water: &HeightField,
    ambient: &[wgpu::TextureView; 2],
) -> [wgpu::BindGroup; 2] {
    water.state().bind_groups(|view| {
        device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: Some("scene + water"),
            layout,
            entries: &[
                wgpu::BindGroupEntry { binding: 0, resource: uniforms.as_entire_binding() },
                wgpu::BindGroupEntry { binding: 1, resource: wgpu::BindingResource::TextureView(view) },
                wgpu::BindGroupEntry { binding: 2, resource: wgpu::BindingResource::TextureView(&ambient[0]) },
                wgpu::BindGroupEntry { binding: 3, resource: wgpu::BindingResource::TextureView(&ambient[1]) },
            ],
        })
    })
}

/// A `size` x `size` ambient map (RGBA32Float: height, slopes of the FFT ocean), filled from
/// the CPU or drawn by the GPU FFT.
pub(super) fn ambient_map(device: &wgpu::Device, size: u32) -> (wgpu::Texture, wgpu::TextureView) {
    let usage = wgpu::TextureUsages::TEXTURE_BINDING | wgpu::TextureUsages::COPY_DST;
    let texture = gpu::texture_2d(device, "ambient map", (size, size, 1), 1, wgpu::TextureFormat::Rgba32Float, usage);
    let view = texture.create_view(&Default::default());
    (texture, view)
}

pub(super) struct DepthBuffer {
    pub(super) view: wgpu::TextureView,
    pub(super) size: (u32, u32),
}

impl Renderer {
    /// Points the renderer at another heightfield (after a change of resolution).
    pub fn rebind_water(&mut self, device: &wgpu::Device, water: &HeightField) {
        self.bind_water(device, water);
    }

    /// Makes the scene passes' group 0 for `water`, and counts the binding
    /// ([`Renderer::water_binding`]).
    pub(super) fn bind_water(&mut self, device: &wgpu::Device, water: &HeightField) {
        self.water_groups = water_bind_groups(device, &self.water_layout, &self.uniforms, water, &self.ambient_views);
        self.water_binding += 1;
    }

    /// How many times group 0 has been made: a scene pass that binds the water and the ambient
    /// maps with uniforms of its own (the flat water's mirrored camera) makes its groups again
    /// when this changes.
    pub fn water_binding(&self) -> u64 {
        self.water_binding
    }

    /// The scene uniforms with each of the water's two state textures and the ambient maps
    /// (group 0 of a scene pass), as [`water_bind_groups`] made them.
    pub fn water_groups(&self) -> &[wgpu::BindGroup; 2] {
        &self.water_groups
    }

    /// Reads the FFT ocean's surface and displacement from `views` (the GPU ocean's outputs)
    /// from now on.
    pub fn use_ambient_views(&mut self, device: &wgpu::Device, water: &HeightField, views: [&wgpu::TextureView; 2]) {
        self.ambient_views = views.map(|v| v.clone());
        self.bind_water(device, water);
    }

    /// Copies the FFT ocean's surface and, with choppiness, its displacement (`size`² texels
    /// each, from `Ocean::surface` and `Ocean::displacement`) into the ambient maps the water
    /// is read with (remade, and `water`'s groups rebound, when the size changes).
    pub fn upload_ambient(
        &mut self,
        device: &wgpu::Device,
        queue: &wgpu::Queue,
        water: &HeightField,
        size: u32,
        maps: [Option<&[[f32; 4]]>; 2],
    ) {
        let cpu_views = [self.cpu_ambient[0].1.clone(), self.cpu_ambient[1].1.clone()];
        if self.cpu_ambient[0].0.width() != size || self.ambient_views != cpu_views {
            if self.cpu_ambient[0].0.width() != size {
                self.cpu_ambient = [ambient_map(device, size), ambient_map(device, size)];
            }
            let views = [self.cpu_ambient[0].1.clone(), self.cpu_ambient[1].1.clone()];
            self.use_ambient_views(device, water, [&views[0], &views[1]]);
        }
        for (map, texels) in self.cpu_ambient.iter().zip(maps) {
            let Some(texels) = texels else { continue };
            gpu::write_texture_2d(queue, &map.0, 0, bytemuck::cast_slice(texels));
        }
    }

    /// Copies the foam amounts into the foam map the surface reads (remade, and rebound, when
    /// the foam's grid changes size). Call before the scene's passes when foam is on.
    pub fn upload_foam(&mut self, device: &wgpu::Device, queue: &wgpu::Queue, foam: &Foam) {
        let size = foam.size();
        if self.scene_textures.foam.0.width() != size {
            self.scene_textures.foam = foam_map(device, size);
            self.textures_group =
                self.scene_textures.bind_group(device, &self.textures_layout, &self.caustics.mips.view);
        }
        gpu::write_texture_2d(queue, &self.scene_textures.foam.0, 0, bytemuck::cast_slice(foam.amount()));
    }

    /// Copies the ambient waves' spectrum image (`AmbientWaves::spectrum_image`) for the
    /// spectrum debug view.
    pub fn upload_spectrum(&self, queue: &wgpu::Queue, image: &[f32]) {
        gpu::write_texture_2d(queue, &self.scene_textures.spectrum.0, 0, bytemuck::cast_slice(image));
    }

    pub(super) fn depth_view(&mut self, device: &wgpu::Device, size: (u32, u32)) -> &wgpu::TextureView {
        if self.depth.as_ref().map(|d| d.size) != Some(size) {
            let texture = gpu::texture_2d(
                device,
                "depth",
                (size.0.max(1), size.1.max(1), 1),
                1,
                DEPTH_FORMAT,
                wgpu::TextureUsages::RENDER_ATTACHMENT,
            );
            self.depth = Some(DepthBuffer { view: texture.create_view(&Default::default()), size });
        }
        &self.depth.as_ref().expect("depth buffer just made").view
    }
}

/// The scene passes' bind group layouts: group 0 (uniforms, the water's state, the ambient
/// maps) and group 1 (textures and samplers).
pub(super) fn scene_layouts(device: &wgpu::Device) -> (wgpu::BindGroupLayout, wgpu::BindGroupLayout) {
    let vis = wgpu::ShaderStages::VERTEX_FRAGMENT;
    let water_layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
        label: Some("scene + water layout"),
        entries: &[
            gpu::uniform_entry(0, vis),
            gpu::float_texture_entry(1, vis),
            gpu::float_texture_entry(2, vis),
            gpu::float_texture_entry(3, vis),
        ],
    });
    let textures_layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
        label: Some("scene textures layout"),
        entries: &[
            gpu::filtered_texture_entry(0, vis),
            gpu::filtered_texture_entry(1, vis),
            gpu::texture_entry(
                2,
                vis,
                wgpu::TextureSampleType::Float { filterable: true },
                wgpu::TextureViewDimension::Cube,
            ),
            gpu::sampler_entry(3, vis),
            gpu::sampler_entry(4, vis),
            gpu::float_texture_entry(5, vis),
            gpu::float_texture_entry(6, vis),
            gpu::float_texture_entry(7, vis),
            gpu::filtered_texture_entry(8, vis),
        ],
    });
    (water_layout, textures_layout)
}
