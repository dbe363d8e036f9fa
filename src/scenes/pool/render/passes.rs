//! The scene's passes in the order a frame draws them: the picture (ray-traced, flat or
//! split, at the view's render scale), the flat water's textures, the scene pass itself.

use super::{regions, PoolPasses};
use crate::gpu::{self, FrameContext};
use crate::render::flat::FlatView;
use crate::render::scene_parts::begin_scene_pass;
use crate::render::{deck, flat_shown, Features, FlatCaustics, RenderMode, Renderer, View};
use crate::sim::HeightField;

/// A picture to draw: its colour target and size (pixels), the view and the water.
#[derive(Clone, Copy)]
struct Picture<'a> {
    target: &'a wgpu::TextureView,
    size: (u32, u32),
    view: &'a View,
    water: &'a HeightField,
}

impl PoolPasses {
    /// Draws sky, pool, sphere and water into the frame's target at the view's render scale,
    /// the split view's divider and the debug view over them. After [`PoolPasses::prepare`] in
    /// the same frame (the mirrored camera's uniforms and groups).
    pub fn encode_pool(
        &mut self,
        renderer: &mut Renderer,
        cx: &mut FrameContext<'_>,
        view: &View,
        water: &HeightField,
    ) {
        let (device, target, size) = (cx.device, cx.target, cx.size);
        let encoder = &mut *cx.encoder;
        let scaled = renderer.scene_size(view, size);
        if scaled != size {
            let image = renderer.upscale_image(device, scaled);
            self.draw_picture(renderer, device, encoder, Picture { target: &image, size: scaled, view, water });
            renderer.upscale_into(encoder, target);
        } else {
            self.draw_picture(renderer, device, encoder, Picture { target, size, view, water });
        }
        if let Some(f) = flat_shown(view).filter(|f| f.mode == RenderMode::Split) {
            self.flat.draw_divider(encoder, target, size, f.divider(size.0));
        }
        if let Some(debug) = view.debug {
            self.debug_pass(renderer, device, debug.texture, view.ambient);
            let mut pass = gpu::colour_pass(encoder, "debug view", target, wgpu::LoadOp::Load);
            let [x, y, w, h] = debug.viewport(size);
            pass.set_viewport(x, y, w, h, 0.0, 1.0);
            let water_group = &renderer.water_groups()[water.state().current()];
            self.debug_passes[&(debug.texture, view.ambient.model, view.ambient.choppy())]
                .draw(&mut pass, &[water_group, renderer.textures_group()]);
        }
    }

    /// The scene at `size` pixels: ray-traced, flat, or flat left of the divider and
    /// ray-traced right of it (two passes on disjoint pixels, so each is shaded once).
    fn draw_picture(
        &mut self,
        renderer: &mut Renderer,
        device: &wgpu::Device,
        encoder: &mut wgpu::CommandEncoder,
        picture: Picture<'_>,
    ) {
        let size = picture.size;
        let Some(f) = flat_shown(picture.view) else {
            self.draw_scene(renderer, device, encoder, picture, None, [0, 0, size.0, size.1]);
            return;
        };
        let divider = f.divider(size.0);
        if divider > 0 {
            self.encode_flat_textures(renderer, device, encoder, picture, &f);
            self.draw_scene(renderer, device, encoder, picture, Some(&f), [0, 0, divider, size.1]);
        }
        if divider < size.0 {
            self.draw_scene(renderer, device, encoder, picture, None, [divider, 0, size.0 - divider, size.1]);
        }
    }

    /// The feature sets a frame of `view` on a `size` target draws with: what
    /// [`PoolPasses::encode_caustics`] and [`PoolPasses::encode_pool`] will ask pipelines
    /// for, in the order they ask (kept in step with them; a test checks that a frame after
    /// [`PoolPasses::build_ahead`] builds nothing).
    pub(super) fn variants_drawn(&self, renderer: &Renderer, view: &View, size: (u32, u32)) -> Vec<Features> {
        let base = view.features();
        let size = renderer.scene_size(view, size);
        let flat = flat_shown(view);
        let traced_shown = flat.is_none_or(|f| f.mode == RenderMode::Split && f.split < 1.0);
        let flat_reads = flat.is_some_and(|f| f.caustics == FlatCaustics::Real);
        let mut drawn = Vec::new();
        if (view.caustics && traced_shown) || flat_reads {
            drawn.push(base);
        }
        let divider = flat.map_or(0, |f| f.divider(size.0));
        if let Some(f) = flat.filter(|_| divider > 0) {
            let lit = f.lit_features(base);
            drawn.extend([Features { clip: 1, ..lit }, Features { clip: -1, ..lit }, lit]);
        }
        if divider < size.0 {
            drawn.push(base);
            let regions = self.object_regions.then(|| regions::surface_regions(view, size)).flatten();
            drawn.extend(regions.into_iter().flatten().map(|(_, needs)| needs));
        }
        let mut seen = std::collections::HashSet::new();
        drawn.retain(|f| seen.insert(*f));
        drawn
    }

    /// The flat water's reflection texture (for tests: what the mirrored camera drew), once
    /// flat water has been drawn.
    #[doc(hidden)]
    pub fn flat_reflection_texture(&self) -> Option<&wgpu::Texture> {
        self.flat.targets.as_ref().map(|t| &t.reflection)
    }

    /// Draws the flat water's reflection (mirrored camera, above the plane, with the sky) and
    /// refraction (below the plane) textures for the picture's size. In a split view only the
    /// columns the flat part can read: left of the divider plus the largest shift.
    fn encode_flat_textures(
        &mut self,
        renderer: &Renderer,
        device: &wgpu::Device,
        encoder: &mut wgpu::CommandEncoder,
        picture: Picture<'_>,
        f: &FlatView,
    ) {
        let Picture { size, view, water, .. } = picture;
        let resolution = f.resolution.clamp(0.25, 1.0);
        let side = |s: u32| ((s as f32 * resolution).round() as u32).max(1);
        let texture_size = (side(size.0), side(size.1));
        let divider = f.divider(size.0);
        let reach = if divider < size.0 {
            let x = divider as f32 / size.0 as f32 + f.strength;
            ((x * texture_size.0 as f32).ceil() as u32 + 2).min(texture_size.0)
        } else {
            texture_size.0
        };
        let lit = f.lit_features(view.features());
        let (reflection, refraction) = (Features { clip: 1, ..lit }, Features { clip: -1, ..lit });
        self.variant(renderer, device, reflection);
        self.variant(renderer, device, refraction);
        let targets = self.flat.targets(device, renderer.settings().target_format, texture_size);
        let (reflection_view, refraction_view, depth) =
            (targets.reflection_view.clone(), targets.refraction_view.clone(), targets.depth.clone());
        let current = water.state().current();
        let passes = [
            ("flat water reflection", &reflection_view, reflection, &self.mirror_groups[current]),
            ("flat water refraction", &refraction_view, refraction, &renderer.water_groups()[current]),
        ];
        for (label, colour, features, group) in passes {
            // Cleared to alpha 0: "nothing here" for the water reading the refraction.
            let mut pass = begin_scene_pass(encoder, label, colour, &depth, Some(wgpu::Color::TRANSPARENT));
            pass.set_scissor_rect(0, 0, reach, texture_size.1);
            pass.set_bind_group(0, Some(group), &[]);
            pass.set_bind_group(1, Some(renderer.textures_group()), &[]);
            self.draw_deck(&mut pass, features, view);
            self.draw_solids(&mut pass, renderer, features, view);
            if features.clip > 0 {
                self.sky.draw(&mut pass, &[group, renderer.textures_group()]);
            }
        }
    }

    /// A scene pass over the pixels `rect` (x, y, width, height) of `target`: the deck, the
    /// objects, the water surface (ray-traced, or flat with `flat`) and the pool, cheapest
    /// first where they hide costly work (early depth testing skips the water the deck and
    /// the objects hide, and the pool the water hides), then the sky where nothing else was
    /// drawn and the objects' outlines over it all. The pass starting at column 0 clears the
    /// target.
    fn draw_scene(
        &mut self,
        renderer: &mut Renderer,
        device: &wgpu::Device,
        encoder: &mut wgpu::CommandEncoder,
        picture: Picture<'_>,
        flat: Option<&FlatView>,
        rect: [u32; 4],
    ) {
        let Picture { target, size, view, water } = picture;
        let depth = renderer.scene_depth(device, size).clone();
        // Everything on the flat side is lit as its refraction texture is (FlatView::lit_features).
        let features = flat.map_or(view.features(), |f| f.lit_features(view.features()));
        let regions = if flat.is_some() || !self.object_regions { None } else { regions::surface_regions(view, size) };
        self.variant(renderer, device, features);
        for (_, needs) in regions.iter().flatten() {
            self.variant(renderer, device, *needs);
        }
        if flat.is_some() {
            self.prepare_flat_pipeline(renderer, device, features);
        }
        let clear = (rect[0] == 0).then_some(wgpu::Color::BLACK);
        let mut pass = begin_scene_pass(encoder, "scene", target, &depth, clear);
        let pipelines = &self.variants[&features];
        let water_group = &renderer.water_groups()[water.state().current()];
        pass.set_bind_group(0, Some(water_group), &[]);
        pass.set_bind_group(1, Some(renderer.textures_group()), &[]);
        let [x, y, w, h] = rect;
        pass.set_scissor_rect(x, y, w, h);
        self.draw_deck(&mut pass, features, view);
        self.draw_bodies(&mut pass, renderer, features, view);
        match (flat, regions) {
            (Some(_), _) => {
                let group = &self.flat.targets.as_ref().expect("flat textures are drawn first").group;
                pass.set_pipeline(self.flat.pipeline(features));
                pass.set_bind_group(2, Some(group), &[]);
                self.grid.draw(&mut pass);
            }
            // The objects are traced only where the water can show them (see surface_regions).
            (None, Some(regions)) => {
                for (region, needs) in regions {
                    if let Some([x, y, w, h]) = overlap(region, rect) {
                        pass.set_pipeline(&self.variants[&needs].surface);
                        pass.set_scissor_rect(x, y, w, h);
                        match regions::grid_band(
                            view,
                            [x, y, w, h],
                            size,
                            (self.grid.n(), renderer.settings().pool.half_width),
                        ) {
                            Some(band) => self.grid.draw_band(&mut pass, &band),
                            None => self.grid.draw(&mut pass),
                        }
                    }
                }
                pass.set_scissor_rect(x, y, w, h);
            }
            (None, None) => {
                pass.set_pipeline(&pipelines.surface);
                self.grid.draw(&mut pass);
            }
        }
        self.draw_pool(&mut pass, features);
        // Past the deck the sky shows only in the rows above its far edge.
        let sky_rows = if view.deck {
            deck::sky_rows(view.view_proj, view.eye, size, renderer.settings().pool.rim).saturating_sub(y).min(h)
        } else {
            h
        };
        if sky_rows > 0 {
            pass.set_scissor_rect(x, y, w, sky_rows);
            self.sky.draw(&mut pass, &[water_group, renderer.textures_group()]);
            pass.set_scissor_rect(x, y, w, h);
        }
        if renderer.body_outlines() {
            self.draw_edges(&mut pass, renderer, features, view);
        }
    }

    /// Draws the deck around the pool if the view has one. Drawn first: where it hides the
    /// water's cut-away side, those costly fragments then fail the depth test.
    fn draw_deck(&self, pass: &mut wgpu::RenderPass<'_>, features: Features, view: &View) {
        if view.deck {
            pass.set_pipeline(&self.variants[&features].deck);
            self.deck_mesh.draw(pass);
        }
    }

    /// Draws the sphere and the duck (those the view has) and the pool with the pipelines of
    /// `features`, front to back.
    fn draw_solids(&self, pass: &mut wgpu::RenderPass<'_>, renderer: &Renderer, features: Features, view: &View) {
        self.draw_bodies(pass, renderer, features, view);
        self.draw_pool(pass, features);
    }

    /// Draws the sphere and the duck (those the view has). Cheap to shade, so drawn before the
    /// water surface: the surface's costly fragments behind their parts above the water then
    /// fail the depth test (their parts under it are drawn for nothing, hidden by the water).
    fn draw_bodies(&self, pass: &mut wgpu::RenderPass<'_>, renderer: &Renderer, features: Features, view: &View) {
        for (k, pipeline) in self.variants[&features].bodies.iter().enumerate() {
            if let (Some(pipeline), Some(_)) = (pipeline, &view.bodies[k]) {
                pass.set_pipeline(pipeline);
                renderer.body_meshes()[k].draw(pass);
            }
        }
    }

    /// Draws the outlines of the bodies that have one (`BodyKind::edge`), blended over
    /// everything else.
    fn draw_edges(&self, pass: &mut wgpu::RenderPass<'_>, renderer: &Renderer, features: Features, view: &View) {
        for (k, pipeline) in self.variants[&features].edges.iter().enumerate() {
            if let (Some(pipeline), Some(_)) = (pipeline, &view.bodies[k]) {
                pass.set_pipeline(pipeline);
                renderer.body_outline_meshes()[k].draw(pass);
            }
        }
    }

    /// Draws the pool's walls and floor; in a pass seen from above the deck only its dry band
    /// (the part under the water shows only through the water, which traces it).
    fn draw_pool(&self, pass: &mut wgpu::RenderPass<'_>, features: Features) {
        pass.set_pipeline(&self.variants[&features].pool);
        let seen_from_deck = features.deck && features.clip == 0;
        if seen_from_deck { &self.dry_band_mesh } else { &self.pool_mesh }.draw(pass);
    }
}

/// The part two rectangles (x, y, width, height) share, if any.
fn overlap(a: [u32; 4], b: [u32; 4]) -> Option<[u32; 4]> {
    let (x0, y0) = (a[0].max(b[0]), a[1].max(b[1]));
    let (x1, y1) = ((a[0] + a[2]).min(b[0] + b[2]), (a[1] + a[3]).min(b[1] + b[3]));
    (x1 > x0 && y1 > y0).then(|| [x0, y0, x1 - x0, y1 - y0])
}
