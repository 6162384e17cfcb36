//! A perspective camera and a fly controller: the view and projection
//! matrices every 3D chapter starts from.

use glam::{Mat4, Vec2, Vec3};
use winit::keyboard::KeyCode;

use crate::Input;

/// Where the eye is, where it looks, and how wide it sees.
///
/// Right-handed, y up. Yaw 0 looks down -z; positive pitch looks up.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Camera {
    pub position: Vec3,
    /// Radians around +y.
    pub yaw: f32,
    /// Radians above the horizon, kept inside (-90°, 90°).
    pub pitch: f32,
    /// Vertical field of view, radians.
    pub fov_y: f32,
    pub aspect: f32,
    pub near: f32,
    pub far: f32,
}

impl Camera {
    /// A camera at `position` looking at `target`.
    pub fn looking_at(position: Vec3, target: Vec3, aspect: f32) -> Self {
        let d = (target - position).normalize();
        Self {
            position,
            yaw: (-d.x).atan2(-d.z),
            pitch: d.y.asin(),
            fov_y: 60f32.to_radians(),
            aspect,
            near: 0.1,
            far: 500.0,
        }
    }

    // ANCHOR: matrices
    /// Unit vector the camera looks along.
    pub fn forward(&self) -> Vec3 {
        let (sy, cy) = self.yaw.sin_cos();
        let (sp, cp) = self.pitch.sin_cos();
        Vec3::new(-sy * cp, sp, -cy * cp)
    }

    /// Unit vector to the camera's right, always horizontal.
    pub fn right(&self) -> Vec3 {
        let (sy, cy) = self.yaw.sin_cos();
        Vec3::new(cy, 0.0, -sy)
    }

    /// World → camera space.
    pub fn view(&self) -> Mat4 {
        Mat4::look_to_rh(self.position, self.forward(), Vec3::Y)
    }

    /// Camera → clip space. glam's `perspective_rh` maps depth to 0..1,
    /// which is what WebGPU expects (OpenGL uses -1..1).
    pub fn projection(&self) -> Mat4 {
        Mat4::perspective_rh(self.fov_y, self.aspect, self.near, self.far)
    }

    /// World → clip space in one matrix.
    pub fn view_projection(&self) -> Mat4 {
        self.projection() * self.view()
    }
    // ANCHOR_END: matrices
}

/// Moves a [`Camera`] like a drone: WASD or arrows to move, Space/E to
/// rise, Shift+Space/Q to fall, mouse to look, scroll to dolly, Ctrl to go
/// fast. Speeds are per second, so motion does not depend on frame rate.
#[derive(Clone, Copy, Debug)]
pub struct FlyController {
    /// Metres per second.
    pub speed: f32,
    /// Radians per pixel of mouse motion.
    pub sensitivity: f32,
    /// Metres per scroll line.
    pub scroll_step: f32,
}

impl Default for FlyController {
    fn default() -> Self {
        Self { speed: 8.0, sensitivity: 0.003, scroll_step: 1.0 }
    }
}

impl FlyController {
    /// Key help for the F1 overlay.
    pub const KEYS: &'static [(&'static str, &'static str)] = &[
        ("W A S D / arrows", "move"),
        ("E / Space", "rise"),
        ("Q / Shift+Space", "fall"),
        ("Ctrl", "move 4x faster"),
        ("left drag, or Tab to lock", "look around"),
        ("scroll", "move forward and back"),
    ];

    // ANCHOR: fly
    pub fn update(&self, camera: &mut Camera, input: &Input, dt: f32) {
        let axis = |plus: &[KeyCode], minus: &[KeyCode]| {
            let on = |keys: &[KeyCode]| keys.iter().any(|&k| input.held(k)) as i32 as f32;
            on(plus) - on(minus)
        };
        let shift = input.held(KeyCode::ShiftLeft) || input.held(KeyCode::ShiftRight);
        let space = input.held(KeyCode::Space);
        let forward = axis(&[KeyCode::KeyW, KeyCode::ArrowUp], &[KeyCode::KeyS, KeyCode::ArrowDown]);
        let right = axis(&[KeyCode::KeyD, KeyCode::ArrowRight], &[KeyCode::KeyA, KeyCode::ArrowLeft]);
        let up = axis(&[KeyCode::KeyE], &[KeyCode::KeyQ]) + if space { if shift { -1.0 } else { 1.0 } } else { 0.0 };
        let fast = input.held(KeyCode::ControlLeft) || input.held(KeyCode::ControlRight);

        let flat_forward = Vec3::new(camera.forward().x, 0.0, camera.forward().z).normalize_or_zero();
        let direction = flat_forward * forward + camera.right() * right + Vec3::Y * up;
        let speed = self.speed * if fast { 4.0 } else { 1.0 };
        camera.position += direction.normalize_or_zero() * speed * dt;
        camera.position += camera.forward() * input.scroll * self.scroll_step;

        self.look(camera, input.look);
    }

    /// Turns the camera by a mouse movement in pixels.
    pub fn look(&self, camera: &mut Camera, delta: Vec2) {
        camera.yaw -= delta.x * self.sensitivity;
        camera.pitch -= delta.y * self.sensitivity;
        // Looking straight up or down makes `look_to` degenerate.
        let limit = 89f32.to_radians();
        camera.pitch = camera.pitch.clamp(-limit, limit);
    }
    // ANCHOR_END: fly
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn looking_at_faces_the_target() {
        let camera = Camera::looking_at(Vec3::new(3.0, 4.0, 5.0), Vec3::new(-1.0, 0.0, 2.0), 1.5);
        let expected = (Vec3::new(-1.0, 0.0, 2.0) - Vec3::new(3.0, 4.0, 5.0)).normalize();
        assert!(camera.forward().distance(expected) < 1e-5, "{:?}", camera.forward());
        assert!(camera.right().dot(camera.forward()).abs() < 1e-5);
    }

    #[test]
    fn projection_maps_near_to_0_and_far_to_1() {
        let camera = Camera::looking_at(Vec3::ZERO, -Vec3::Z, 1.0);
        let clip = |z: f32| {
            let p = camera.view_projection() * Vec3::new(0.0, 0.0, z).extend(1.0);
            p.z / p.w
        };
        assert!((clip(-camera.near) - 0.0).abs() < 1e-5);
        assert!((clip(-camera.far) - 1.0).abs() < 1e-4);
        assert!(clip(-10.0) > 0.0 && clip(-10.0) < 1.0);
    }

    #[test]
    fn motion_is_frame_rate_independent() {
        let controller = FlyController::default();
        let mut input = Input::default();
        input.key_down(KeyCode::KeyW);
        let start = Camera::looking_at(Vec3::ZERO, -Vec3::Z, 1.0);
        let (mut slow, mut fast) = (start, start);
        controller.update(&mut slow, &input, 1.0 / 10.0);
        for _ in 0..10 {
            controller.update(&mut fast, &input, 1.0 / 100.0);
        }
        assert!(slow.position.distance(fast.position) < 1e-4);
        assert!((slow.position.z + controller.speed / 10.0).abs() < 1e-4);
    }

    #[test]
    fn pitch_is_clamped() {
        let controller = FlyController::default();
        let mut camera = Camera::looking_at(Vec3::ZERO, -Vec3::Z, 1.0);
        controller.look(&mut camera, Vec2::new(0.0, -1e6));
        assert!(camera.pitch < 90f32.to_radians() && camera.forward().y > 0.99);
    }
}
