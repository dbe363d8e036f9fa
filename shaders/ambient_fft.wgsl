// Tessendorf's FFT ocean on the GPU, in fragment passes (so WebGL2 runs the same code): the
// spectrum pass advances each wave of a lattice (the pool's, a sea cascade's) analytically, h = a0 e^{-i w t} +
// a1 e^{+i w t} with w^2 = g k tanh(k D) (1 + (k/k_m)^2), and packs the height and slope
// spectra as two complex signals per texel; then log2(N) Stockham stages along the rows and
// log2(N) along the columns sum the waves (inverse DFT). With choppiness a second chain sums
// the horizontal displacement D = sum(-i k/|k| h e^{ik.x}) and its derivatives.
// ambient/ocean.rs runs the very same arithmetic on the CPU (`advance`, `advance_choppy`,
// `stockham_source`).

struct FftStage {
    // x: half-block of this stage (1, 2, ... N/2); y: 0 along rows, 1 along columns;
    // z: time since the spectrum's epoch (s), for the spectrum pass.
    params: vec4<f32>,
    // The lattice's band, for the spectrum pass: x: pi / half the tile's side (rad/m, the
    // wavenumber of one lattice step); y: the water's depth (m).
    band: vec4<f32>,
};

@group(0) @binding(0) var<uniform> stage: FftStage;
// The spectrum pass: a0, a1 per lattice point (ocean.rs epoch_spectrum). A stage: the
// previous stage's output, two complex signals per texel.
@group(0) @binding(1) var source: texture_2d<f32>;

fn complex_mul(a: vec2<f32>, b: vec2<f32>) -> vec2<f32> {
    return vec2<f32>(a.x * b.x - a.y * b.y, a.x * b.y + a.y * b.x);
}

// Angular frequency (rad/s) of a wave of wavenumber k (rad/m): gravity on water of the band's
// depth, and surface tension (ambient.rs angular_frequency_in). tanh's argument is capped at 9
// (tanh 9 = 1 - 3e-8): some GPUs compute tanh from exponentials that overflow to inf/inf.
fn wave_frequency(k: f32) -> f32 {
    let ratio = k / CAPILLARY_WAVENUMBER;
    return sqrt(GRAVITY * k * tanh(min(k * stage.band.y, 9.0)) * (1.0 + ratio * ratio));
}

// Wavenumber (rad/m) of lattice index i along one axis: indices past N/2 are negative.
fn lattice_k(i: i32, n: i32) -> f32 {
    return f32(select(i - n, i, i < n / 2)) * stage.band.x;
}

// This texel's wavevector (rad/m) and its wave h = a0 e^{-i w dt} + a1 e^{i w dt}.
fn advanced_wave(position: vec4<f32>) -> mat2x2<f32> {
    let texel = vec2<i32>(position.xy);
    let n = i32(textureDimensions(source).x);
    let a = textureLoad(source, texel, 0);
    let k = vec2<f32>(lattice_k(texel.x, n), lattice_k(texel.y, n));
    let phase = wave_frequency(length(k)) * stage.params.z;
    let turn = vec2<f32>(cos(phase), sin(phase));
    return mat2x2<f32>(k, complex_mul(a.xy, vec2<f32>(turn.x, -turn.y)) + complex_mul(a.zw, turn));
}

// 1/|k|, 0 at k = 0 (no wave there).
fn inverse_k(k: vec2<f32>) -> f32 {
    return select(0.0, 1.0 / length(k), dot(k, k) > 0.0);
}

@fragment
fn fs_ocean_spectrum(in: FullscreenOut) -> @location(0) vec4<f32> {
    let wave = advanced_wave(in.position);
    let k = wave[0];
    let h = wave[1];
    // h + i (i kx h), and i kz h + i (kx kz / k) h (dh/dz, and dDx/dz for choppiness).
    let c = k.y + k.x * k.y * inverse_k(k);
    return vec4<f32>(h - k.x * h, -c * h.y, c * h.x);
}

@fragment
fn fs_ocean_choppy_spectrum(in: FullscreenOut) -> @location(0) vec4<f32> {
    let wave = advanced_wave(in.position);
    let k = wave[0];
    let h = wave[1];
    let r = inverse_k(k);
    // Dx + i Dz = (kz/k - i kx/k) h, and dDx/dx + i dDz/dz = (kx^2/k + i kz^2/k) h.
    return vec4<f32>(complex_mul(vec2<f32>(k.y * r, -k.x * r), h), complex_mul(vec2<f32>(k.x * k.x * r, k.y * k.y * r), h));
}

@fragment
fn fs_ocean_stage(in: FullscreenOut) -> @location(0) vec4<f32> {
    let texel = vec2<i32>(in.position.xy);
    let n = i32(textureDimensions(source).x);
    let half = i32(stage.params.x);
    let along_columns = stage.params.y > 0.5;
    let i = select(texel.x, texel.y, along_columns);
    // Output i = in[j] +- w in[j + n/2]: block b, place r in it, twiddle index q.
    let b = i / (2 * half);
    let r = i % (2 * half);
    let q = r % half;
    let j = b * half + q;
    let angle = PI * f32(q) / f32(half);
    let w = vec2<f32>(cos(angle), sin(angle));
    let sign = select(-1.0, 1.0, r < half);
    let at0 = select(vec2<i32>(j, texel.y), vec2<i32>(texel.x, j), along_columns);
    let at1 = select(vec2<i32>(j + n / 2, texel.y), vec2<i32>(texel.x, j + n / 2), along_columns);
    let x0 = textureLoad(source, at0, 0);
    let x1 = textureLoad(source, at1, 0);
    return x0 + sign * vec4<f32>(complex_mul(w, x1.xy), complex_mul(w, x1.zw));
}
