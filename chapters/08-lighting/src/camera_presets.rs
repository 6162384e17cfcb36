//! Where the camera goes: the aerial view the chapter starts from, the
//! glass sphere's close-up for the shading views, the places worth seeing
//! (street, rooftop, lollipop, hill, skyline, landscape, billboard, moving
//! parts), and the cameras that ride a car or a drone. Each is a function
//! of the city (or of where a car or drone is), used by the view table and
//! the overlay's buttons alike.

use common::Camera;
use common::glam::Vec3;

use crate::billboard::Billboard;
use crate::city::{City, Traffic};
use crate::material_spheres;
use crate::moving_parts::MovingParts;
use crate::paths;
use crate::scenery::billboard;

/// Where a preset puts the camera; a mode leaves it, and the "reset
/// camera" button takes it back to the aerial view. The seed's city had
/// camera buttons for places worth seeing; these are this city's.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum CameraPreset {
    /// Close to the glass sphere ([`sphere_camera`]).
    Sphere,
    /// In front of the material spheres ([`material_spheres_camera`]).
    MaterialSpheres,
    /// Riding behind the first car ([`follow_camera`]) until the learner moves.
    Follow,
    /// At eye height in the avenue along x = 0 ([`street_camera`]).
    Street,
    /// On the roof of the tallest tower ([`rooftop_camera`]).
    Rooftop,
    /// Beside the lollipop tower's ball ([`lollipop_camera`]).
    Lollipop,
    /// On the hill in the north-east corner ([`hill_camera`]).
    Hill,
    /// Riding beside the drone over the hill ([`drone_camera`]) until the learner moves.
    Drone,
    /// Outside the south-east corner, at eye height ([`skyline_camera`]).
    Skyline,
    /// Over the countryside north of the city ([`landscape_camera`]).
    Landscape,
    /// In front of the billboard on its hill ([`billboard_camera`]).
    Billboard,
    /// Facing the tallest tower's crown and sign ([`moving_parts_camera`]).
    MovingParts,
}

impl CameraPreset {
    /// The overlay's camera buttons: every place but the sphere's close-up,
    /// which the shading views use.
    pub const PLACES: [(&'static str, CameraPreset); 10] = [
        ("street", CameraPreset::Street),
        ("rooftop", CameraPreset::Rooftop),
        ("lollipop", CameraPreset::Lollipop),
        ("hill", CameraPreset::Hill),
        ("skyline", CameraPreset::Skyline),
        ("landscape", CameraPreset::Landscape),
        ("billboard", CameraPreset::Billboard),
        ("moving parts", CameraPreset::MovingParts),
        ("follow a car", CameraPreset::Follow),
        ("ride a drone", CameraPreset::Drone),
    ];

    /// The camera this preset places in `city` with its `traffic` now, and
    /// what it then rides with, if anything.
    pub fn place(self, city: &City, traffic: &Traffic, aspect: f32) -> (Camera, Option<Riding>) {
        let still = |camera| (camera, None);
        match self {
            Self::Sphere => still(sphere_camera(city, aspect)),
            Self::MaterialSpheres => still(material_spheres_camera(aspect)),
            Self::Street => still(street_camera(aspect)),
            Self::Rooftop => still(rooftop_camera(city, aspect)),
            Self::Lollipop => still(lollipop_camera(aspect)),
            Self::Hill => still(hill_camera(aspect)),
            Self::Skyline => still(skyline_camera(aspect)),
            Self::Landscape => still(landscape_camera(aspect)),
            Self::Billboard => still(billboard_camera(&billboard(), aspect)),
            Self::MovingParts => still(moving_parts_camera(&MovingParts::new(city), aspect)),
            Self::Follow | Self::Drone => {
                // The drone over the hill: nothing stands between it and the city.
                let riding = if self == Self::Follow { Riding::Car(0) } else { Riding::Drone(3) };
                (riding.camera(traffic, aspect), Some(riding))
            }
        }
    }
}

/// Something moving that the camera rides with, placed anew every frame
/// from where it is then, until the learner moves the camera.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Riding {
    /// Behind this car ([`follow_camera`]).
    Car(usize),
    /// Beside this drone ([`drone_camera`]).
    Drone(usize),
}

impl Riding {
    pub fn camera(self, traffic: &Traffic, aspect: f32) -> Camera {
        match self {
            Riding::Car(car) => follow_camera(&traffic.cars[car], aspect),
            Riding::Drone(drone) => drone_camera(traffic.drones[drone], aspect),
        }
    }
}

// ANCHOR: cameras
/// High over the south-west corner, looking at the middle of the city.
pub fn aerial_camera(aspect: f32) -> Camera {
    Camera {
        near: 0.5,
        far: 900.0,
        ..Camera::looking_at(Vec3::new(-190.0, 120.0, 230.0), Vec3::new(0.0, 10.0, 0.0), aspect)
    }
}

/// Standing in the road along x = 0, at the southern edge, looking north.
pub fn street_camera(aspect: f32) -> Camera {
    Camera {
        near: 0.3,
        far: 900.0,
        ..Camera::looking_at(Vec3::new(-3.0, 1.8, 185.0), Vec3::new(-3.0, 8.0, 0.0), aspect)
    }
}

/// Close to the glass sphere, from the south-west, with the morning sun on it.
pub fn sphere_camera(city: &City, aspect: f32) -> Camera {
    let centre = city.sphere_building + Vec3::Y * 24.0;
    Camera { near: 0.3, far: 900.0, ..Camera::looking_at(centre + Vec3::new(-18.0, 6.0, 34.0), centre, aspect) }
}

/// South of the material spheres, looking north at them with the city
/// behind, just far enough back to see both rows whole.
pub fn material_spheres_camera(aspect: f32) -> Camera {
    let centre = material_spheres::CENTRE;
    Camera { near: 0.3, far: 900.0, ..Camera::looking_at(centre + Vec3::Z * 19.0, centre, aspect) }
}

/// Behind and above a car, looking where it goes.
pub fn follow_camera(car: &paths::Pose, aspect: f32) -> Camera {
    let ahead = car.forward();
    let eye = car.position - ahead * 12.0 + Vec3::Y * 4.5;
    Camera { near: 0.3, far: 900.0, ..Camera::looking_at(eye, car.position + ahead * 12.0, aspect) }
}
// ANCHOR_END: cameras

// ANCHOR: places
/// A camera at `eye` looking at `target`, seeing as far as the city needs.
fn city_camera(eye: Vec3, target: Vec3, aspect: f32) -> Camera {
    Camera { near: 0.3, far: 900.0, ..Camera::looking_at(eye, target, aspect) }
}

/// On the roof of the tallest square tower, near the edge that faces the
/// glass sphere (the roof's cap behind), looking down past the sphere
/// across the city.
pub fn rooftop_camera(city: &City, aspect: f32) -> Camera {
    let tower = city.tallest_tower().model;
    let roof = tower.transform_point3(Vec3::Y * 0.5);
    let towards = (city.sphere_building - roof).with_y(0.0).normalize();
    let eye = roof + towards * 0.4 * tower.x_axis.length() + Vec3::Y * 1.7;
    city_camera(eye, roof.with_y(0.0) + towards * 170.0, aspect)
}

/// Beside the lollipop's glowing ball (at 74 m, block (−30, 30)), a little
/// above it, looking down past it at the blocks to the south-east.
pub fn lollipop_camera(aspect: f32) -> Camera {
    let ball = Vec3::new(-30.0, 74.2, 30.0);
    city_camera(ball + Vec3::new(-20.0, 4.0, -15.0), ball + Vec3::new(40.0, -60.0, 50.0), aspect)
}

/// Standing on the east slope of the hill that fills the north-east
/// corner block, at the city's edge, looking south along it: the towers on
/// the right, the ground ending on the left.
pub fn hill_camera(aspect: f32) -> Camera {
    city_camera(Vec3::new(172.0, 13.3, -150.0), Vec3::new(176.0, 6.0, 150.0), aspect)
}

/// Beside a drone, a little above it and further out from the middle of
/// the city, looking past it at the towers.
pub fn drone_camera(drone: Vec3, aspect: f32) -> Camera {
    let outwards = Vec3::new(drone.x, 0.0, drone.z).normalize_or(Vec3::Z);
    let aside = Vec3::Y.cross(outwards);
    let eye = drone + outwards * 7.0 + aside * 3.0 + Vec3::Y * 1.5;
    city_camera(eye, drone - outwards * 40.0 + aside * 8.0 - Vec3::Y * 12.0, aspect)
}

/// Far out past the south-east corner, 20 m up, looking at the middle of
/// the city: its skyline.
pub fn skyline_camera(aspect: f32) -> Camera {
    city_camera(Vec3::new(235.0, 16.0, 235.0), Vec3::new(0.0, 30.0, 0.0), aspect)
}

/// A camera at `eye` looking at `target`, seeing past the countryside's
/// far edge (1 km out from the middle of the city, both ways).
fn countryside_camera(eye: Vec3, target: Vec3, aspect: f32) -> Camera {
    Camera { near: 0.3, far: 2500.0, ..Camera::looking_at(eye, target, aspect) }
}

/// 24 m over the river's south bank, east of the road north, looking
/// north-west across the river, its beaches and the bridge, to the
/// billboard's hill.
pub fn landscape_camera(aspect: f32) -> Camera {
    countryside_camera(Vec3::new(170.0, 24.0, -300.0), Vec3::new(10.0, 0.0, -480.0), aspect)
}

/// In front of the billboard, a little below its middle and 45 m out,
/// looking up at it.
pub fn billboard_camera(billboard: &Billboard, aspect: f32) -> Camera {
    let eye = billboard.centre + billboard.facing * 45.0 + billboard.across * 8.0 - Vec3::Y * 6.0;
    countryside_camera(eye, billboard.centre, aspect)
}

/// East of the tallest tower, over the avenue, looking at the face the
/// sign rides up, the crown on the roof above it.
pub fn moving_parts_camera(parts: &MovingParts, aspect: f32) -> Camera {
    let target = parts.sign_face.with_y((parts.sign_low + parts.crown_base.y) / 2.0);
    city_camera(target + Vec3::new(75.0, -5.0, 40.0), target, aspect)
}
// ANCHOR_END: places

#[cfg(test)]
mod tests {
    use super::*;
    use crate::city::{Material, Shape};
    use crate::countryside;
    use crate::scenery::billboard;

    #[test]
    fn the_drone_camera_keeps_its_drone_in_view_as_it_bobs() {
        let city = City::new();
        let mut heights = Vec::new();
        for drone_time in [0.0, 0.8, 1.7, 6.0] {
            let traffic = city.traffic(0.0, drone_time);
            let (camera, riding) = CameraPreset::Drone.place(&city, &traffic, 16.0 / 9.0);
            assert_eq!(riding, Some(Riding::Drone(3)));
            let clip = camera.view_projection() * traffic.drones[3].extend(1.0);
            let (x, y) = (clip.x / clip.w, clip.y / clip.w);
            assert!(clip.w > 0.0 && x.abs() < 0.8 && y.abs() < 0.8, "the drone is at ({x}, {y}) in the picture");
            heights.push(camera.position.y);
        }
        assert!(heights.windows(2).all(|h| h[0] != h[1]), "the camera bobs with the drone: {heights:?}");
    }

    #[test]
    fn the_preset_views_keep_their_subjects_in_the_picture() {
        let city = City::new();
        let traffic = city.traffic(6.0, 6.0);
        let parts = MovingParts::new(&city);
        let board = billboard();
        let in_view = |preset: CameraPreset, point: Vec3| {
            let camera = preset.place(&city, &traffic, 16.0 / 9.0).0;
            let clip = camera.view_projection() * point.extend(1.0);
            clip.w > 0.0 && (clip.x / clip.w).abs() < 0.95 && (clip.y / clip.w).abs() < 0.95
        };
        for corner in board.corners() {
            assert!(in_view(CameraPreset::Billboard, corner), "the billboard's corner {corner}");
        }
        assert!(in_view(CameraPreset::Landscape, board.centre), "the billboard from the landscape view");
        let bridge = Vec3::new(0.0, countryside::BRIDGE_DECK, countryside::river_z(0.0));
        assert!(in_view(CameraPreset::Landscape, bridge), "the bridge");
        let crown = parts.crown_base + Vec3::Y * 6.0;
        let sign = parts.sign_face.with_y(parts.sign_height(6.0));
        assert!(in_view(CameraPreset::MovingParts, crown) && in_view(CameraPreset::MovingParts, sign));
    }

    #[test]
    fn the_rooftop_camera_stands_over_every_other_square_tower() {
        let city = City::new();
        let camera = rooftop_camera(&city, 16.0 / 9.0);
        let roofs = city
            .pieces
            .iter()
            .filter(|p| p.shape == Shape::Cube && matches!(p.material, Material::Facade | Material::Brick))
            .map(|p| p.model.transform_point3(Vec3::Y * 0.5).y);
        let highest = roofs.fold(0.0, f32::max);
        assert!((camera.position.y - (highest + 1.7)).abs() < 1e-3, "{} over a roof at {highest}", camera.position.y);
    }
}
