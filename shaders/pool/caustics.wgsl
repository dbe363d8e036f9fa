// Caustics map. Every water grid triangle is sent along the refracted sunlight to the pool
// floor; where the waves focus light the triangle shrinks, and its brightness is the ratio
// of its calm-surface area to its projected area (energy conservation), summed additively.
// The map is indexed by where a calm surface would have let the light in (see light_entry),
// so any underwater point can look its light up. Red: light; green: light with the shadows
// of the sphere and the duck. The rim's shadow is in both. With dispersion the map is drawn
// once per colour (CAUSTICS_CHANNEL, written ahead of this file), refracting by that colour's
// index, into its own channel with the shadows (green's without them in alpha).

struct CausticsOut {
    @builtin(position) clip: vec4<f32>,
    @location(0) calm_entry: vec2<f32>,
    @location(1) wavy_entry: vec2<f32>,
    @location(2) visibility: vec2<f32>,
};

@vertex
fn vs_caustics(@location(0) grid: vec2<f32>) -> CausticsOut {
    let xz = grid * half_width();
    let state = water_at(xz);
    let p = vec3<f32>(xz.x, state.x, xz.y);
    let ior = select(IOR_WATER, scene.ior[CAUSTICS_CHANNEL], HAS_DISPERSION);
    let ray = refract(-scene.sun.xyz, water_normal(state), IOR_AIR / ior);
    let t_floor = (-depth() - p.y) / min(ray.y, -1.0e-4);
    let on_floor = p + ray * t_floor;
    let entry = light_entry(on_floor);
    var out: CausticsOut;
    out.clip = vec4<f32>(entry / half_width(), 0.0, 1.0);
    out.calm_entry = xz;
    out.wavy_entry = entry;
    let rim_light = rim_visibility(p);
    // The floor is lit: at the refracted ray's end, and t_floor past the surface for the part
    // of a body above the water (behind the segment's origin on its line to the sun).
    let sphere_light = objects_visibility(p, ray, t_floor, t_floor) * objects_visibility(p, scene.sun.xyz, 10.0, -t_floor);
    out.visibility = vec2<f32>(rim_light, rim_light * sphere_light);
    return out;
}

fn area(a: vec2<f32>, b: vec2<f32>) -> f32 {
    return abs(a.x * b.y - a.y * b.x);
}

@fragment
fn fs_caustics(in: CausticsOut) -> @location(0) vec4<f32> {
    let calm = area(dpdx(in.calm_entry), dpdy(in.calm_entry));
    let wavy = area(dpdx(in.wavy_entry), dpdy(in.wavy_entry));
    let intensity = min(calm / max(wavy, 1.0e-12), 40.0);
    // Stored divided by the map's scale (1 for float maps; an 8-bit map clips at 1.0).
    let light = intensity * in.visibility / scene.water.w;
    if (HAS_DISPERSION) {
        // The pipeline's write mask keeps this draw's channel(s).
        return vec4<f32>(light.y, light.y, light.y, light.x);
    }
    return vec4<f32>(light, 0.0, 1.0);
}
