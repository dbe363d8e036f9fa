// The tiles' glaze (render/glaze.rs): a clear coat of index GLAZE_IOR mirrors the share
// fresnel(n·v, n_medium / GLAZE_IOR) of the light reaching it, 4 % head on in air and far more
// at a grazing view: the sky, and the sun as a normalised Blinn–Phong highlight
// ((s + 8) / 8π cos^s of the half vector's angle). Each tile's face rounds off at its edges, so
// its top edge catches the sky even where the flat face would mirror the water below.

// The glaze's normal on the face with normal n at tile coordinates uv (m): tilted towards
// the nearer edges over the outer GLAZE_ROUNDING of each half tile, up to GLAZE_EDGE_SLOPE at
// the edge; flat where a pixel spans more than a few texels (lod), where it would sparkle.
fn glaze_normal(n: vec3<f32>, uv: vec2<f32>, lod: f32) -> vec3<f32> {
    let across = fract(uv * TILES_PER_METRE) * 2.0 - 1.0;
    let rounding = smoothstep(vec2<f32>(1.0 - GLAZE_ROUNDING), vec2<f32>(1.0), abs(across));
    let slope = sign(across) * rounding * GLAZE_EDGE_SLOPE * (1.0 - smoothstep(2.0, 3.5, lod));
    // tile_uv's axes: u along x (along z on the walls facing x), v down the walls (along z on
    // the floor).
    let on_floor = abs(n.y) > 0.5;
    let u_axis = select(select(vec3<f32>(1.0, 0.0, 0.0), vec3<f32>(0.0, 0.0, 1.0), abs(n.x) > 0.5), vec3<f32>(1.0, 0.0, 0.0), on_floor);
    let v_axis = select(vec3<f32>(0.0, -1.0, 0.0), vec3<f32>(0.0, 0.0, 1.0), on_floor);
    return normalize(n + slope.x * u_axis + slope.y * v_axis);
}

// Light the glaze of a tile in air mirrors towards the eye (linear, scene units). n: the
// glaze's normal (glaze_normal); to_eye and to_sun: unit vectors from the tile; sun: the sun's
// light arriving (shadows included, not the cosine); coat: the glaze's cover at the texel (the
// tile texture's alpha, 0 on the grout). Under the water the glaze mirrors a tenth as much
// (water's 1.33 against GLAZE_IOR), which no pixel shows: it is left out there, and in the water's mirror,
// where it would cost every pixel of water a second tile shading for a few pixels' sheen.
fn glaze_light(n: vec3<f32>, to_eye: vec3<f32>, to_sun: vec3<f32>, sun: vec3<f32>, coat: f32) -> vec3<f32> {
    // A rounded edge turned away from the eye shows nothing (fresnel would take it as grazing).
    let facing = dot(n, to_eye);
    let share = fresnel(facing, IOR_AIR / GLAZE_IOR) * step(0.0, facing) * coat * scene.pool.w;
    let half_vector = normalize(to_eye + to_sun);
    let lobe = (GLAZE_SHININESS + 8.0) / (8.0 * PI) * pow(max(dot(n, half_vector), 0.0), GLAZE_SHININESS);
    // The sky along the mirrored ray; one pointing down meets the water and the far wall, dim
    // beside it, and is left out.
    let r = reflect(-to_eye, n);
    let sky = textureSampleLevel(sky_cube, clamp_sampler, r, 0.0).rgb * SKY_RANGE * smoothstep(-0.05, 0.05, r.y);
    return share * (lobe * max(dot(n, to_sun), 0.0) * sun + sky);
}

// The glaze of the tile at p (above the water, seen directly from the eye) with face normal n,
// glaze cover coat, at tile mip level lod, where the objects let sun_through of the sun pass.
fn tile_glaze(p: vec3<f32>, n: vec3<f32>, coat: f32, lod: f32, sun_through: f32) -> vec3<f32> {
    let to_eye = normalize(scene.eye.xyz - p);
    return glaze_light(glaze_normal(n, tile_uv(p, n), lod), to_eye, scene.sun.xyz, sun_through * sun_light(), coat);
}
