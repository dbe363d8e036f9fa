// The water surface: the grid displaced by the simulated height. Per fragment, the view ray
// is split at the surface into a reflected and a refracted ray (Snell, n = 1.333); each is
// traced analytically to the pool, the sphere or the sky, and the two are blended by the
// Fresnel reflectance for unpolarised light.

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

// Seen from above: reflection of sky and rim, refraction into the pool.
@fragment
fn fs_above(in: SurfaceOut) -> @location(0) vec4<f32> {
    let n = water_normal(water_at(in.world.xz));
    let view = normalize(in.world - scene.eye.xyz);
    let reflected = reflect(view, n);
    let refracted = refract(view, n, IOR_AIR / IOR_WATER);
    let lod_refracted = tile_lod(pool_exit(in.world, refracted));
    let lod_reflected = tile_lod(pool_exit(in.world, reflected));
    let f = fresnel(dot(-view, n), IOR_AIR / IOR_WATER);
    let colour = mix(trace_water(in.world, refracted, lod_refracted), trace_air(in.world, reflected, lod_reflected), f);
    return finish(colour);
}

// Seen from below: refraction out to the sky inside Snell's window, total internal
// reflection of the pool outside it, all dimmed by the water between eye and surface.
@fragment
fn fs_below(in: SurfaceOut) -> @location(0) vec4<f32> {
    let n = -water_normal(water_at(in.world.xz));
    let view = normalize(in.world - scene.eye.xyz);
    let reflected = reflect(view, n);
    let refracted = refract(view, n, IOR_WATER / IOR_AIR);
    let lod_refracted = tile_lod(pool_exit(in.world, refracted));
    let lod_reflected = tile_lod(pool_exit(in.world, reflected));
    let f = fresnel(dot(-view, n), IOR_WATER / IOR_AIR);
    var out_colour = vec3<f32>(0.0);
    if (f < 1.0) {
        out_colour = trace_air(in.world, refracted, lod_refracted);
    }
    var colour = mix(out_colour, trace_water(in.world, reflected, lod_reflected), f);
    colour *= exp(-WATER_ABSORPTION * water_path(scene.eye.xyz, in.world, half_width(), depth()));
    return finish(colour);
}
