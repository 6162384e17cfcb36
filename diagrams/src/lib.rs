//! The book's diagrams, drawn as SVG by code. Plots are computed with the
//! chapters' own functions (fog visibility, Perlin octaves, frustum
//! culling, the sun's path, depth precision, the sea's grid), so a diagram
//! cannot disagree with the code it explains. `cargo xtask book` writes
//! them into `book/src/diagrams/` on every build.
//!
//! `kit` is the SVG kit; every other module draws one chapter's figures
//! and is named after that chapter's package.

mod kit;

mod camera;
mod fog;
mod instancing;
mod lighting;
mod shadows;
mod skybox;
mod terrain;
mod textures;
mod triangle;
mod voronoi_water;
mod water;

/// Every diagram, as (file name, SVG text).
pub fn all() -> Vec<(&'static str, String)> {
    vec![
        ("clip-space.svg", triangle::clip_space()),
        ("frustum-side.svg", camera::frustum_side()),
        ("depth-precision.svg", camera::depth_precision()),
        ("multisampling.svg", camera::multisampling()),
        ("fbm-octaves.svg", terrain::fbm_octaves()),
        ("frustum-culling.svg", terrain::frustum_culling()),
        ("lod-quadtree.svg", terrain::lod_quadtree()),
        ("lod-morph.svg", terrain::lod_morph()),
        ("fog-curve.svg", fog::fog_curve()),
        ("instancing-buffers.svg", instancing::instancing_buffers()),
        ("pixel-quads.svg", instancing::pixel_quads()),
        ("rock-culling.svg", instancing::culling_flow()),
        ("sun-path.svg", skybox::sun_path()),
        ("mirrored-camera.svg", water::mirrored_camera()),
        ("projective-texturing.svg", water::projective_texturing()),
        ("light-falloff.svg", lighting::light_falloff()),
        ("spot-cone.svg", lighting::spot_cone()),
        ("half-vector.svg", lighting::half_vector()),
        ("clusters.svg", lighting::clusters_side()),
        ("bloom-chain.svg", lighting::bloom_chain()),
        ("lambert-cosine.svg", lighting::lambert_cosine()),
        ("tone-curves.svg", lighting::tone_curves()),
        ("bloom-knee.svg", lighting::bloom_knee()),
        ("downsample-taps.svg", lighting::downsample_taps()),
        ("fxaa.svg", lighting::fxaa()),
        ("microfacet-terms.svg", lighting::microfacet_terms()),
        ("white-furnace.svg", lighting::white_furnace()),
        ("prefiltered-lobe.svg", lighting::prefiltered_lobe()),
        ("tangent-from-uvs.svg", textures::tangent_from_uvs()),
        ("texel-footprint.svg", textures::texel_footprint()),
        ("footprints.svg", textures::footprints()),
        ("srgb-curve.svg", textures::srgb_curve()),
        ("srgb-steps.svg", textures::srgb_steps()),
        ("wrap-modes.svg", textures::wrap_modes()),
        ("flat-interpolation.svg", textures::flat_interpolation()),
        ("normal-map.svg", textures::normal_map()),
        ("green-up.svg", textures::green_up()),
        ("shadow-test.svg", shadows::shadow_test()),
        ("light-box-fit.svg", shadows::light_box_fit()),
        ("shadow-acne.svg", shadows::shadow_acne()),
        ("cube-shadow-map.svg", shadows::cube_shadow_map()),
        ("voronoi-cones.svg", voronoi_water::voronoi_cones()),
        ("jump-flooding.svg", voronoi_water::jump_flooding()),
        ("moving-grid.svg", voronoi_water::moving_grid()),
        ("sail-swell.svg", voronoi_water::sail_swell()),
    ]
}
