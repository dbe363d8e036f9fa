// Debug views of the simulation's textures, drawn over the scene (full screen or an inset;
// the viewport places it). The pool's square maps onto the view, +x to the right, +z down.
//   1 height: signed colour map, red above rest, blue below, full colour at 5 mm
//   2 normals: the surface normal as colour (4x, y, 4z) * 0.5 + 0.5 (slopes exaggerated 4x so
//     ripples show), flat water is (0.5, 1, 0.5)
//   3 velocity: signed colour map, full colour at 0.05 m/s
//   4 caustics: the caustics map's light (with the sphere's shadow), 1 = calm-surface light at 40%
//     (as the map holds it, before the scene raises it to caustic_contrast)
//   6 spectrum: the ambient waves' amplitude per wavevector (kx right, kz down, 0 in the
//     middle), black 1 um to white 1 cm on a log scale through blue and orange; grey rings at
//     the 0.9 m and 0.2 m wavelengths the models' waves lie between
// With ambient waves (AMBIENT_MODEL), height and normals are those of the surface drawn: the
// simulation's plus the waves'.

// Grey at 0, towards red for +1 and towards blue for -1 (values beyond are clamped).
fn signed_colour(t: f32) -> vec3<f32> {
    let grey = vec3<f32>(0.5);
    let c = clamp(t, -1.0, 1.0);
    return select(mix(grey, vec3<f32>(0.1, 0.3, 1.0), -c), mix(grey, vec3<f32>(1.0, 0.25, 0.05), c), c >= 0.0);
}

@fragment
fn fs_debug(in: FullscreenOut) -> @location(0) vec4<f32> {
    // DEBUG_TEXTURE (1-4, above) is a constant written ahead of this file: one pass per view.
    let mode = DEBUG_TEXTURE;
    // Nearest cell of the state texture, so single cells stay visible.
    let n = i32(scene.water.x);
    let cell = clamp(vec2<i32>(in.uv * scene.water.x), vec2<i32>(0), vec2<i32>(n - 1));
    var state = textureLoad(water_state, cell, 0);
    if (AMBIENT_MODEL != AMBIENT_NONE) {
        // The surface the renderer draws: the simulation plus the ambient waves at the cell.
        state = with_ambient(state, ((vec2<f32>(cell) + 0.5) / scene.water.x * 2.0 - 1.0) * half_width());
    }
    var colour: vec3<f32>;
    if (mode == 1) {
        colour = signed_colour(state.x / 0.005);
    } else if (mode == 2) {
        let n = water_normal(state);
        colour = vec3<f32>(4.0 * n.x, n.y, 4.0 * n.z) * 0.5 + 0.5;
    } else if (mode == 3) {
        colour = signed_colour(state.y / 0.05);
    } else if (mode == 6) {
        let n = f32(textureDimensions(ambient_spectrum).x);
        let cell = vec2<i32>(in.uv * n);
        let level = clamp((textureLoad(ambient_spectrum, cell, 0).r + 6.0) / 4.0, 0.0, 1.0);
        colour = mix(mix(vec3<f32>(0.0), vec3<f32>(0.1, 0.3, 1.0), smoothstep(0.0, 0.5, level)),
                     vec3<f32>(1.0, 0.85, 0.5), smoothstep(0.5, 1.0, level));
        // Wavenumber here (rad/m): cells are pi/W apart.
        let k = length((in.uv - 0.5) * n) * PI / half_width();
        let pixel = fwidth(k);
        for (var r = 0; r < 2; r++) {
            let ring = 2.0 * PI / select(AMBIENT_SHORTEST, AMBIENT_LONGEST, r == 0);
            if (abs(k - ring) < pixel) {
                colour = vec3<f32>(0.6);
            }
        }
    } else {
        // The caustics map is indexed by light entry point: v runs along -z (see caustics_uv).
        let light = textureSampleLevel(caustics_map, clamp_sampler, vec2<f32>(in.uv.x, 1.0 - in.uv.y), 0.0).g * scene.water.w;
        colour = vec3<f32>(1.0, 0.95, 0.8) * light * 0.4;
    }
    // The colours above are meant as displayed: decode to linear (no tone curve), then
    // sRGB-encode like every other pass.
    let c = pow(clamp(colour, vec3<f32>(0.0), vec3<f32>(1.0)), vec3<f32>(2.2));
    if (ENCODE_SRGB) {
        return vec4<f32>(linear_to_srgb(c), 1.0);
    }
    return vec4<f32>(c, 1.0);
}
