//! The billboard on the hill across the river: a panel on two posts,
//! facing the city, the chapter's number on it in seven-segment digits (the
//! city project lit its author's student number on a dark hill), and three
//! spot lights at its foot aimed up at it, which come on as night falls.

use common::glam::{Mat4, Vec2, Vec3};

use crate::city::{Material, Piece, Shape};
use crate::lights::{Light, LightKind};

/// The panel's size, metres, and how high its lower edge is over the ground.
pub const WIDTH: f32 = 32.0;
pub const HEIGHT: f32 = 11.0;
const CLEARANCE: f32 = 7.0;
const THICKNESS: f32 = 0.6;
/// What the panel says.
pub const TEXT: &str = "08";

/// The billboard: where it stands, its pieces and its lights.
pub struct Billboard {
    /// The middle of the panel's front face.
    pub centre: Vec3,
    /// Unit, horizontal: the way the panel faces.
    pub facing: Vec3,
    /// Unit, horizontal: to the right of someone looking at the panel.
    pub across: Vec3,
    /// The panel, its posts and its digits.
    pub pieces: Vec<Piece>,
    /// The spots at full strength (see [`Billboard::lights`]).
    spots: Vec<Light>,
}

// ANCHOR: spots
impl Billboard {
    /// The billboard at `site` on ground whose height `ground` gives,
    /// facing `towards` (a point on the ground plane, x and z).
    pub fn new(site: Vec2, towards: Vec2, ground: impl Fn(Vec2) -> f32) -> Self {
        let flat = (towards - site).normalize();
        let facing = Vec3::new(flat.x, 0.0, flat.y);
        let across = Vec3::Y.cross(facing);
        let foot = Vec3::new(site.x, ground(site), site.y);
        let middle = foot + Vec3::Y * (CLEARANCE + HEIGHT / 2.0);
        let placed = |centre: Vec3, size: Vec3| {
            Mat4::from_cols(
                (across * size.x).extend(0.0),
                (Vec3::Y * size.y).extend(0.0),
                (facing * size.z).extend(0.0),
                centre.extend(1.0),
            )
        };
        let mut pieces = vec![Piece {
            shape: Shape::Cube,
            model: placed(middle, Vec3::new(WIDTH, HEIGHT, THICKNESS)),
            material: Material::Billboard,
        }];
        for side in [-1.0, 1.0] {
            let post = foot + across * side * WIDTH * 0.35 + Vec3::Y * (CLEARANCE + HEIGHT / 2.0) / 2.0 - facing;
            let size = Vec3::new(0.8, CLEARANCE + HEIGHT / 2.0 + 1.0, 0.8);
            pieces.push(Piece { shape: Shape::Cylinder, model: placed(post, size), material: Material::Metal });
        }
        let centre = middle + facing * THICKNESS / 2.0;
        for (u, v, size) in digit_segments(TEXT) {
            let at = centre + across * u + Vec3::Y * v + facing * 0.15;
            pieces.push(Piece {
                shape: Shape::Cube,
                model: placed(at, size.extend(0.3)),
                material: Material::CarPaint,
            });
        }
        // ANCHOR: billboard_spots
        // Three spots 14 m in front, a metre over the ground, each aimed at
        // the middle of its third of the panel, whose corners are up to 25°
        // off its axis: full light out to 26°, fading to nothing at 34°.
        let spots = [-1.0, 0.0, 1.0]
            .map(|k| {
                let spot = foot.with_y(0.0) + facing * 14.0 + across * k * WIDTH / 3.0;
                let position = spot.with_y(ground(Vec2::new(spot.x, spot.z)) + 1.0);
                let aim = centre + across * k * WIDTH / 3.0;
                Light {
                    position,
                    colour: Vec3::new(1.0, 0.93, 0.8) * 260.0,
                    range: 45.0,
                    kind: LightKind::Spot {
                        direction: (aim - position).normalize(),
                        inner: 26f32.to_radians(),
                        outer: 34f32.to_radians(),
                    },
                }
            })
            .to_vec();
        // ANCHOR_END: billboard_spots
        Self { centre, facing, across, pieces, spots }
    }

    /// The spots as they shine with night at `night` (0 by day, 1 at
    /// night), as the street lamps do: none by day, dimmed at dusk.
    pub fn lights(&self, night: f32) -> Vec<Light> {
        if night <= 0.0 {
            return Vec::new();
        }
        self.spots.iter().map(|l| Light { colour: l.colour * night, ..*l }).collect()
    }

    /// The four corners of the panel's front face.
    pub fn corners(&self) -> [Vec3; 4] {
        let (x, y) = (self.across * WIDTH / 2.0, Vec3::Y * HEIGHT / 2.0);
        [self.centre - x - y, self.centre + x - y, self.centre + x + y, self.centre - x + y]
    }
}
// ANCHOR_END: spots

/// Segments a to g of a seven-segment digit, as bits 0 to 6.
const DIGITS: [u8; 10] = [0x3F, 0x06, 0x5B, 0x4F, 0x66, 0x6D, 0x7D, 0x07, 0x7F, 0x6F];

/// The boxes that write `text` (digits; anything else is a gap) on the
/// panel: (across, up, size) from the panel's centre, metres.
pub fn digit_segments(text: &str) -> Vec<(f32, f32, Vec2)> {
    let (w, h, stroke, pitch) = (4.6, 8.0, 1.0, 7.0);
    let count = text.chars().count() as f32;
    let bars = [
        (0.0, h / 2.0 - stroke / 2.0, Vec2::new(w, stroke)),
        (w / 2.0 - stroke / 2.0, h / 4.0, Vec2::new(stroke, h / 2.0)),
        (w / 2.0 - stroke / 2.0, -h / 4.0, Vec2::new(stroke, h / 2.0)),
        (0.0, -h / 2.0 + stroke / 2.0, Vec2::new(w, stroke)),
        (-w / 2.0 + stroke / 2.0, -h / 4.0, Vec2::new(stroke, h / 2.0)),
        (-w / 2.0 + stroke / 2.0, h / 4.0, Vec2::new(stroke, h / 2.0)),
        (0.0, 0.0, Vec2::new(w, stroke)),
    ];
    let mut boxes = Vec::new();
    for (i, c) in text.chars().enumerate() {
        let Some(bits) = c.to_digit(10).map(|d| DIGITS[d as usize]) else { continue };
        let left = (i as f32 - (count - 1.0) / 2.0) * pitch;
        for (segment, &(u, v, size)) in bars.iter().enumerate() {
            if bits & (1 << segment) != 0 {
                boxes.push((left + u, v, size));
            }
        }
    }
    boxes
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A billboard on flat ground at the origin, facing +z.
    fn flat() -> Billboard {
        Billboard::new(Vec2::ZERO, Vec2::new(0.0, 100.0), |_| 0.0)
    }

    /// The light the spots bring to `point` on the panel's front face
    /// (radiance × n · l, summed): what Lambert's term multiplies by the albedo.
    fn arriving(board: &Billboard, point: Vec3) -> f32 {
        board
            .lights(1.0)
            .iter()
            .map(|light| {
                let l = (light.position - point).normalize();
                light.reaching(point).length() * board.facing.dot(l).max(0.0)
            })
            .sum()
    }

    #[test]
    fn the_spots_light_the_whole_panel_and_little_else() {
        let board = flat();
        let centre = arriving(&board, board.centre);
        assert!(centre > 0.5, "the middle of the panel gets {centre}");
        for corner in board.corners() {
            let light = arriving(&board, corner);
            assert!(light > 0.2 * centre, "a corner at {corner} gets {light}, the middle {centre}");
        }
        // Aimed, not flooding: 10 m past either side, nothing much.
        for outside in
            [board.centre + board.across * (WIDTH / 2.0 + 10.0), board.centre - board.across * (WIDTH / 2.0 + 10.0)]
        {
            let light = arriving(&board, outside);
            assert!(light < 0.05 * centre, "{light} reaches {outside}");
        }
    }

    /// The comment in `Billboard::new`: each third's corners are within
    /// the inner cone of the spot aimed at it.
    #[test]
    fn each_third_of_the_panel_is_inside_its_spots_inner_cone() {
        let board = flat();
        let mut widest = 0f32;
        for (k, light) in [-1.0, 0.0, 1.0].iter().zip(board.lights(1.0)) {
            let LightKind::Spot { direction, inner, .. } = light.kind else { panic!("a spot") };
            let middle = board.centre + board.across * *k * WIDTH / 3.0;
            for (u, v) in [(-1.0, -1.0), (1.0, -1.0), (1.0, 1.0), (-1.0, 1.0)] {
                let corner = middle + board.across * u * WIDTH / 6.0 + Vec3::Y * v * HEIGHT / 2.0;
                let angle = direction.angle_between(corner - light.position);
                widest = widest.max(angle);
                assert!(angle < inner, "{}° off the axis", angle.to_degrees());
            }
        }
        assert!((widest.to_degrees() - 25.3).abs() < 0.1, "the widest corner is {}° off", widest.to_degrees());
    }

    #[test]
    fn the_spots_come_on_with_the_night() {
        let board = flat();
        assert!(board.lights(0.0).is_empty(), "no spots by day");
        let (dusk, night) = (board.lights(0.5), board.lights(1.0));
        assert_eq!(night.len(), 3);
        for (d, n) in dusk.iter().zip(&night) {
            assert_eq!(d.colour, n.colour * 0.5);
            assert!(matches!(n.kind, LightKind::Spot { .. }));
        }
    }

    #[test]
    fn the_digits_are_written_on_the_panel() {
        // 0 lights six segments, 8 all seven.
        assert_eq!(digit_segments("08").len(), 13);
        assert_eq!(digit_segments("1").len(), 2);
        for (u, v, size) in digit_segments(TEXT) {
            assert!(u.abs() + size.x / 2.0 < WIDTH / 2.0 && v.abs() + size.y / 2.0 < HEIGHT / 2.0);
        }
        let board = flat();
        let segments = board.pieces.iter().filter(|p| p.material == Material::CarPaint).count();
        assert_eq!(segments, digit_segments(TEXT).len());
    }
}
