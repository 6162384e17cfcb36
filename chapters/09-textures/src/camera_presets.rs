//! Where each view puts the camera, and in which scene: above the city,
//! on the stage in front of the featured model or the wall, close over
//! the sphere's pole, or standing on the sampling lab's checkerboard.

use common::Camera;
use common::glam::Vec3;

use crate::scenes::Scene;

/// Where a preset puts the camera, and in which scene.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum CameraPreset {
    /// Above the city (chapter 08's aerial camera): where the chapter
    /// starts, and where "reset camera" takes the modes.
    City,
    /// In front of the stage, on the featured model.
    Car,
    /// The left of the stage: the wall, the sphere, the torus and the
    /// cone, in a low sun from the side.
    Wall,
    /// The whole stage from the front, a little above.
    WholeStage,
    /// Close over the top of the stage's sphere, where its texture's u
    /// lines circle the pole: where one tangent per triangle strays
    /// furthest from one per vertex.
    SphereTop,
    /// Standing on the sampling lab's checkerboard, looking to the horizon.
    Lab,
}

impl CameraPreset {
    /// The scene this preset is in, and the camera there for a target of `aspect`.
    pub fn place(self, aspect: f32) -> (Scene, Camera) {
        let at = |eye: Vec3, target: Vec3| Camera { near: 0.1, far: 900.0, ..Camera::looking_at(eye, target, aspect) };
        match self {
            Self::City => (Scene::City, lighting::aerial_camera(aspect)),
            Self::Car => (Scene::Stage, at(Vec3::new(-3.3, 1.9, 4.3), Vec3::new(0.2, 0.7, 0.0))),
            Self::Wall => (Scene::Stage, at(Vec3::new(-2.2, 1.5, 0.9), Vec3::new(-6.4, 0.9, -3.6))),
            Self::WholeStage => (Scene::Stage, at(Vec3::new(0.0, 4.2, 10.5), Vec3::new(0.0, 1.0, -2.0))),
            Self::SphereTop => (Scene::Stage, at(Vec3::new(-3.95, 2.15, -2.85), Vec3::new(-3.8, 1.5, -3.3))),
            Self::Lab => (
                Scene::Lab,
                Camera {
                    near: 0.1,
                    far: 1500.0,
                    ..Camera::looking_at(Vec3::new(0.0, 1.7, 0.0), Vec3::new(0.0, 0.0, -30.0), aspect)
                },
            ),
        }
    }
}
