// The water surface: the grid displaced by the simulated height. Per fragment, the view ray
// is split at the surface into a reflected and a refracted ray (Snell, n = 1.333); each is
// traced analytically to the pool, the sphere or the sky, and the two are blended by the
// Fresnel reflectance (the exact equations for unpolarised light, or a model a lesson picks).

struct SurfaceOut {
    @builtin(position) clip: vec4<f32>,
    @location(0) world: vec3<f32>,
};

@vertex
fn vs_surface(@location(0) grid: vec2<f32>) -> SurfaceOut {
    let xz = grid * half_width();
    let height = water_at(xz).x;
    var out: SurfaceOut;
    out.world = vec3<f32>(xz.x, height, xz.y);
    out.clip = scene.view_proj * vec4<f32>(out.world, 1.0);
    return out;
}

// One fragment shader for both sides, so the grid is drawn once. Front faces are the
// surface seen from above: the reflected ray goes up into the air, the refracted one down
// into the pool. Back faces are seen from below: the refracted ray leaves through Snell's
// window to the sky, the reflected one (all of it beyond the critical angle) stays in the
// water, and everything is dimmed by the water between eye and surface. Both rays are traced
// without branching on the side, so screen derivatives (tile_lod) stay in uniform control flow.
@fragment
fn fs_surface(in: SurfaceOut, @builtin(front_facing) from_above: bool) -> @location(0) vec4<f32> {
    let n = select(-1.0, 1.0, from_above) * water_normal(water_at(in.world.xz));
    let eta = select(IOR_WATER / IOR_AIR, IOR_AIR / IOR_WATER, from_above);
    let view = normalize(in.world - scene.eye.xyz);
    let reflected = reflect(view, n);
    let refracted = refract(view, n, eta);
    let air_dir = upward(select(refracted, reflected, from_above));
    let water_dir = select(reflected, refracted, from_above);
    let t_air = pool_exit_distance(in.world, air_dir);
    let t_water = pool_exit_distance(in.world, water_dir);
    let lod_air = tile_lod(in.world + air_dir * t_air);
    let lod_water = tile_lod(in.world + water_dir * t_water);
    let r = reflectance(dot(-view, n), eta);
    if (SHOW_REFLECTANCE) {
        return grey_as_displayed(r);
    }
    let air_weight = select(1.0 - r, r, from_above);
    let air = trace_air(in.world, air_dir, select(vec3<f32>(0.0), n, from_above), t_air, lod_air);
    let water = trace_water(in.world, water_dir, t_water, lod_water);
    var colour = mix(water, air, air_weight);
    if (!from_above) {
        colour = through_water(colour, scene.eye.xyz, in.world);
    }
    return finish(colour);
}
