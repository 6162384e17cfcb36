//! Chapter 08: lighting. A futuristic city by day and by night: the sun by
//! time of day, hundreds of street lamps, lit buildings and car headlights,
//! shaded flat, per vertex (Gouraud) or per fragment (Phong), with Phong or
//! Blinn-Phong highlights; rendered in HDR, with bloom and tone mapping; and
//! the lights culled per cluster, so that a fragment only visits the few
//! that can reach it. Around the city, the countryside: ground coloured by
//! its height, a river with tides, trees and roads; on the towers, parts
//! that move; across the river, a billboard lit by spot lights.
//!
//! The modules below come in the order the book's lessons teach them; the
//! re-exports after them are the pieces later chapters compose.

// The sun by time of day; point and spot lights, how they fall off, their cones.
pub mod lights;
// The three terms a surface reflects, one at a time: ambient, diffuse, specular.
pub mod light_terms;
// The city's pieces on the GPU: normals of scaled pieces; shaded flat, Gouraud or Phong.
pub mod city_meshes;
// How cars and drones move: paths, poses, clocks that pause.
pub mod paths;
// The city as data: pieces, materials, lamps, traffic.
pub mod city;
// Parts of buildings that move: a turning crown, a sliding sign.
pub mod moving_parts;
// The billboard on the hill, lit by spot lights.
pub mod billboard;
// The lights that shine in a frame, and the bench's extra beacons.
pub mod frame_lights;
// Which lights reach which cluster of the view.
pub mod clusters;
// The frame's camera, sun, lights and cluster lists as group 0 of `lights.wgsl`.
pub mod scene_lights;
// How many lights the loop visits per pixel: what culling saves.
pub mod lights_per_pixel;
// The bright light, blurred wide.
pub mod bloom;
// From the HDR picture to the screen: HDR target, bloom, tone map, FXAA.
pub mod post;
// Smoothing the finished picture's edges: FXAA.
pub mod fxaa;
// Physically based shading: microfacets, GGX, Smith, Schlick; the split-sum table.
pub mod pbr;
// The sky as a light: its radiance in nine spherical harmonics, by compute.
pub mod irradiance;
// The sky as a mirror: a cube map blurred by roughness, level by level, by compute.
pub mod prefiltered_sky;
// Two rows of spheres, rougher left to right: paint above, gold below.
pub mod material_spheres;
// The sky over the city.
pub mod city_sky;
// Around the city: ground by a height function, a river with tides, trees, roads.
pub mod countryside;
// The scene assembled for the GPU: meshes, models, the billboard, the materials.
pub mod scenery;
// Where the camera goes: the aerial view, the sphere's close-up, the places, the rides.
pub mod camera_presets;
// The views, written once, and the settings each applies.
pub mod views;
// The chapter itself: `impl Chapter`, which wires the pieces into a frame.
pub mod demo;

pub use camera_presets::{
    CameraPreset, Riding, aerial_camera, billboard_camera, drone_camera, follow_camera, hill_camera, landscape_camera,
    lollipop_camera, rooftop_camera, skyline_camera, sphere_camera, street_camera,
};
pub use city_meshes::{GpuInstance, GpuMaterial, faceted};
pub use city_sky::CitySky;
pub use demo::LightingChapter;
pub use frame_lights::{LightCount, beacons, frame_lights};
pub use fxaa::Fxaa;
pub use light_terms::LightTerm;
pub use post::{HDR_FORMAT, HdrTarget, PostChain, PostOutput, PostSettings, ToneMap};
pub use scene_lights::{Highlight, LoopOptions, MAX_LIGHTS, SceneLights};
pub use scenery::billboard;
pub use views::{Display, Settings, Shading, VIEW_TABLE};
