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

/// Where a camera stands and which way it looks, as the overlay's camera
/// line shows it and `--camera X,Y,Z,YAW,PITCH` takes it: the position in
/// metres, yaw and pitch in degrees. The text is written here once, in one
/// format, so what a learner copies from the overlay is a flag that puts
/// any run of the chapter (a window, `--screenshot`, `--bench`) in the same
/// place. The optics (field of view, near and far planes) are the
/// chapter's, not part of the place.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CameraPlace {
    pub position: Vec3,
    /// Radians, as [`Camera::yaw`].
    pub yaw: f32,
    /// Radians, as [`Camera::pitch`].
    pub pitch: f32,
}

impl CameraPlace {
    /// The steepest pitch a place may have, in degrees: looking straight up
    /// or down leaves no "up" for the view matrix.
    pub const MAX_PITCH_DEGREES: f64 = 89.99;
    /// Decimals the text gives: a centimetre, a hundredth of a degree.
    pub const DECIMALS: usize = 2;
    /// What the text looks like, for messages and `--help`.
    pub const FORMAT: &'static str = "X,Y,Z,YAW,PITCH";

    /// Where `camera` is.
    pub fn of(camera: &Camera) -> Self {
        Self { position: camera.position, yaw: camera.yaw, pitch: camera.pitch }
    }

    /// Puts `camera` here, keeping its optics.
    pub fn put(self, camera: &mut Camera) {
        camera.position = self.position;
        camera.yaw = self.yaw;
        camera.pitch = self.pitch;
    }
}

/// `X,Y,Z,YAW,PITCH` with [`CameraPlace::DECIMALS`] decimals: the yaw
/// wrapped into [-180°, 180°) (a learner may have turned round many times),
/// the pitch within ±[`CameraPlace::MAX_PITCH_DEGREES`], so the text always
/// reads back.
impl std::fmt::Display for CameraPlace {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let d = Self::DECIMALS;
        let p = self.position;
        let yaw = (f64::from(self.yaw).to_degrees() + 180.0).rem_euclid(360.0) - 180.0;
        let pitch = f64::from(self.pitch).to_degrees().clamp(-Self::MAX_PITCH_DEGREES, Self::MAX_PITCH_DEGREES);
        // Rounding must not print -0.00, nor 180.00 for a yaw just under it.
        let tidy = |v: f64| {
            let scale = 10f64.powi(d as i32);
            let rounded = (v * scale).round() / scale;
            if rounded == 0.0 { 0.0 } else { rounded }
        };
        let yaw = if tidy(yaw) >= 180.0 { -180.0 } else { tidy(yaw) };
        write!(
            f,
            "{:.d$},{:.d$},{:.d$},{:.d$},{:.d$}",
            tidy(p.x.into()),
            tidy(p.y.into()),
            tidy(p.z.into()),
            yaw,
            tidy(pitch)
        )
    }
}

/// Reads `X,Y,Z,YAW,PITCH` (any number of decimals, spaces allowed); the
/// error says what was wrong and what is expected, for a one-line message.
/// Degrees become radians in double precision, so a camera written with
/// enough digits reads back to the very same `f32`s.
impl std::str::FromStr for CameraPlace {
    type Err = String;

    fn from_str(text: &str) -> Result<Self, String> {
        let expected = format!(
            "expected {}: five numbers separated by commas, the position in metres then yaw and pitch in \
             degrees, like 10,2.5,-30,45,-10",
            Self::FORMAT
        );
        let parts: Vec<&str> = text.split(',').map(str::trim).collect();
        let [x, y, z, yaw, pitch] = parts[..] else {
            return Err(format!("{} value{} given; {expected}", parts.len(), if parts.len() == 1 { "" } else { "s" }));
        };
        let number = |name: &str, part: &str| match part.parse::<f64>() {
            Ok(v) if v.is_finite() => Ok(v),
            Ok(_) => Err(format!("{name} is {part}, not a finite number; {expected}")),
            Err(_) => Err(format!("{name} '{part}' is not a number; {expected}")),
        };
        let [x, y, z, yaw, pitch] =
            [("X", x), ("Y", y), ("Z", z), ("YAW", yaw), ("PITCH", pitch)].map(|(name, part)| number(name, part));
        let (x, y, z, yaw, pitch) = (x?, y?, z?, yaw?, pitch?);
        if pitch.abs() > Self::MAX_PITCH_DEGREES {
            return Err(format!(
                "PITCH {pitch}° is steeper than ±{}° (straight up or down leaves the view no up)",
                Self::MAX_PITCH_DEGREES
            ));
        }
        // A number past f32's range (1e39) would become infinite.
        let single = |name: &str, given: f64, value: f64| {
            let narrow = value as f32;
            if narrow.is_finite() { Ok(narrow) } else { Err(format!("{name} {given} is too large; {expected}")) }
        };
        Ok(Self {
            position: Vec3::new(single("X", x, x)?, single("Y", y, y)?, single("Z", z, z)?),
            yaw: single("YAW", yaw, yaw.to_radians())?,
            pitch: single("PITCH", pitch, pitch.to_radians())?,
        })
    }
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

    /// Cameras a learner could fly to: odd positions, yaw turned past a
    /// whole turn either way, pitch up to the limit.
    fn cameras() -> Vec<Camera> {
        let base = Camera::looking_at(Vec3::ZERO, -Vec3::Z, 1.5);
        let mut cameras = Vec::new();
        for i in 0..200 {
            let t = i as f32;
            cameras.push(Camera {
                position: Vec3::new(t * 37.123 - 3000.0, (t * 0.731).sin() * 400.0, -t * 11.0077),
                yaw: (t - 100.0) * 0.173,
                pitch: ((t * 0.37).sin() * 89.99f32).to_radians(),
                ..base
            });
        }
        cameras
    }

    /// What the overlay prints reads back as the same camera, within the
    /// decimals printed (half a unit of the last one), and the view looks
    /// the same way: compared by direction, so a yaw wrapped into
    /// [-180°, 180°) is the same yaw.
    #[test]
    fn the_printed_place_reads_back_within_its_precision() {
        let half = 0.5 * 10f32.powi(-(CameraPlace::DECIMALS as i32));
        for camera in cameras() {
            let text = CameraPlace::of(&camera).to_string();
            let place: CameraPlace = text.parse().unwrap_or_else(|e| panic!("{text}: {e}"));
            let mut back = camera;
            place.put(&mut back);
            let slack = half + camera.position.abs().max_element() * f32::EPSILON;
            assert!((back.position - camera.position).abs().max_element() <= slack, "{text}: {back:?}");
            let turned = (back.yaw - camera.yaw).to_degrees().rem_euclid(360.0);
            assert!(turned.min(360.0 - turned) <= half + 1e-3, "{text}: yaw {} vs {}", back.yaw, camera.yaw);
            assert!((back.pitch - camera.pitch).to_degrees().abs() <= half + 1e-3, "{text}");
            // The chord between the two directions is the angle between
            // them, in radians, this close (acos of a dot near 1 is not
            // precise in f32).
            let chord = (back.forward() - camera.forward()).length();
            assert!(chord < (2.0 * half).to_radians() + 1e-6, "{text}: {}° apart", chord.to_degrees());
            assert_eq!((back.fov_y, back.near, back.far, back.aspect), (camera.fov_y, camera.near, camera.far, 1.5));
        }
    }

    #[test]
    fn the_text_is_five_numbers_yaw_wrapped_and_pitch_kept_readable() {
        let camera = Camera {
            position: Vec3::new(1.0, -2.5, 1000.125),
            yaw: 370f32.to_radians(),
            pitch: 0.0,
            ..Camera::looking_at(Vec3::ZERO, -Vec3::Z, 1.0)
        };
        assert_eq!(CameraPlace::of(&camera).to_string(), "1.00,-2.50,1000.13,10.00,0.00");
        let down = Camera { pitch: -89.999f32.to_radians(), yaw: (-180.001f32).to_radians(), ..camera };
        let text = CameraPlace::of(&down).to_string();
        assert!(text.ends_with(",180.00,-89.99") || text.ends_with(",-180.00,-89.99"), "{text}");
        assert!(text.parse::<CameraPlace>().is_ok(), "{text}");
        let tiny = Camera { position: Vec3::new(-0.001, 0.0, 0.0), yaw: -0.00001, ..camera };
        assert_eq!(CameraPlace::of(&tiny).to_string(), "0.00,0.00,0.00,0.00,0.00", "no -0.00");
    }

    /// Written with every digit, a camera reads back to the same `f32`s,
    /// so a headless picture from it is the same picture.
    #[test]
    fn every_digit_reads_back_exactly() {
        for camera in cameras() {
            let p = camera.position;
            let text = format!(
                "{},{},{},{},{}",
                p.x,
                p.y,
                p.z,
                f64::from(camera.yaw).to_degrees(),
                f64::from(camera.pitch).to_degrees()
            );
            let place: CameraPlace = text.parse().unwrap();
            assert_eq!(place, CameraPlace::of(&camera), "{text}");
        }
    }

    #[test]
    fn bad_places_say_what_is_expected() {
        let cases = [
            ("1,2,3,4", "4 values given; expected X,Y,Z,YAW,PITCH"),
            ("1,2,3,4,5,6", "6 values given"),
            ("", "1 value given"),
            ("1,2,three,4,5", "Z 'three' is not a number"),
            ("1,2,3,NaN,5", "YAW is NaN, not a finite number"),
            ("1,inf,3,4,5", "Y is inf, not a finite number"),
            ("1,2,3,4,90", "PITCH 90° is steeper than ±89.99°"),
            ("1,2,3,4,-89.995", "PITCH -89.995° is steeper"),
            ("1e39,2,3,4,5", "X 1000000000000000000000000000000000000000 is too large"),
        ];
        for (text, start) in cases {
            let error = text.parse::<CameraPlace>().unwrap_err();
            assert!(error.contains(start), "{text}: {error}");
            assert!(!error.contains('\n'), "one line: {error}");
        }
        let place: CameraPlace = " 10, 2.5 ,-30,45,-89.99".parse().unwrap();
        assert_eq!(place.position, Vec3::new(10.0, 2.5, -30.0));
        assert!((place.yaw.to_degrees() - 45.0).abs() < 1e-4 && (place.pitch.to_degrees() + 89.99).abs() < 1e-4);
    }

    #[test]
    fn pitch_is_clamped() {
        let controller = FlyController::default();
        let mut camera = Camera::looking_at(Vec3::ZERO, -Vec3::Z, 1.0);
        controller.look(&mut camera, Vec2::new(0.0, -1e6));
        assert!(camera.pitch < 90f32.to_radians() && camera.forward().y > 0.99);
    }
}
