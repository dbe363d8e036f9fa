// The rubber duck's outline (bodies/duck.rs, with body_duck.wgsl): the pass that blends it
// over what lies behind, drawn after everything else where the kind has an outline.

// The duck's outline without stair-steps: its outline mesh (its traced parts, coarse), each
// part grown by DUCK_EDGE_GROWTH (m, in the duck's frame) along its normals, is drawn after
// everything else. The pixel's ray passes each part's centre at m in its unit-ball space (1 on
// its outline); against m's change to the next pixel that gives the share of the pixel the
// part covers. The nearest part whose outline crosses the pixel, in front of whatever part the
// ray hits, is blended over what was drawn by its share, from its own grown part's fragment
// (where grown parts overlap, once). Its creases are fs_duck's. The eyes, drawn only, not
// traced, keep their stair-steps (a few pixels), and the head's outline may blend over them.
const DUCK_EDGE_GROWTH: f32 = 0.016;

@vertex
fn vs_duck_edge(@location(0) position: vec3<f32>, @location(1) normal: vec3<f32>, @location(2) colour: vec3<f32>, @location(3) part: u32) -> DuckOut {
    var out = duck_vertex(position, normal, colour, part);
    out.world = grown_rim(out.world, out.normal, DUCK_EDGE_GROWTH * scene.bodies[DUCK_SLOT + 3].w);
    out.clip = scene.view_proj * vec4<f32>(out.world, 1.0);
    return out;
}

@fragment
fn fs_duck_edge(in: DuckOut) -> @location(0) vec4<f32> {
    let eye = scene.eye.xyz;
    let dir = normalize(in.world - eye);
    let to_duck = transpose(duck_rotation());
    let o_duck = to_duck * (eye - scene.bodies[DUCK_SLOT + 3].xyz);
    let d_duck = to_duck * dir;
    // The part the ray enters first, and where (m along it).
    var first = -1;
    var hit_t = NO_HIT;
    for (var i = 0; i < DUCK_PARTS; i++) {
        let r = duck_part_ray(o_duck, d_duck, i);
        if (r.hits && r.enter < hit_t) {
            first = i;
            hit_t = r.enter;
        }
    }
    // The nearest outline crossing the pixel in front of what the ray hits: the share of the
    // pixel its part covers, and how near the centre the middle of that share passes.
    var part = -1;
    var cover = 0.0;
    var along = NO_HIT;
    var inside = 1.0;
    for (var i = 0; i < DUCK_PARTS; i++) {
        let r = duck_part_ray(o_duck, d_duck, i);
        let spread = max(fwidth(r.miss), 1.0e-6);
        let share = clamp(0.5 - (r.miss - 1.0) / spread, 0.0, 1.0);
        let in_front = i == first || r.enter < hit_t;
        if (share > 0.0 && share < 1.0 && in_front && r.enter > 0.0 && r.enter < along) {
            part = i;
            cover = share;
            along = r.enter;
            inside = clamp(1.0 - 0.5 * share * spread, 0.0, 1.0);
        }
    }
    // Nothing to blend: returned clear rather than discarded (see grown_rim).
    if (part < 0 || u32(part) != in.part) {
        return vec4<f32>(0.0);
    }
    // Coloured where the middle of the covered share sees the part: the outline itself faces
    // away from the eye, where the coat mirrors most.
    let r = duck_part_ray(o_duck, d_duck, part);
    let radii = scene.bodies[DUCK_SLOT + 5 + 3 * part + 1].xyz;
    let ahead = normalize(d_duck / radii);
    let side = normalize(r.point - dot(r.point, ahead) * ahead);
    let unit = side * inside - ahead * sqrt(1.0 - inside * inside);
    let p = duck_rotation() * (scene.bodies[DUCK_SLOT + 5 + 3 * part].xyz + unit * radii) + scene.bodies[DUCK_SLOT + 3].xyz;
    // Across the water from the eye the water's own pass has the pixel.
    if (across_water(p)) {
        return vec4<f32>(0.0);
    }
    let n = normalize(duck_rotation() * (unit / radii));
    let albedo = scene.bodies[DUCK_SLOT + 5 + 3 * part + 2].rgb;
    let out = seen_directly(duck_shade(p, n, albedo, normalize(p - eye), lit_under(p), true), p);
    return vec4<f32>(out.rgb, cover);
}
