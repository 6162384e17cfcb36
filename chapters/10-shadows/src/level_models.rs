//! The level on the GPU: its models (the blocks baked into one, one per
//! prop kind, the lantern and the player) with their materials, every
//! instance in one buffer, and the draw lists the passes take: everything
//! for the sun's map and the camera's pass, everything but the lantern for
//! the lantern's own cube.

use std::ops::Range;
use std::path::Path;

use common::glam::Mat4;
use common::{Gpu, anyhow, wgpu};
use textures::materials::{Materials, Uploader};
use textures::mesh::{GpuModel, ModelInstance};
use textures::{Draw, DrawList, obj, upload_model};

use crate::game::{Game, Level, PropKind};
use crate::scene;

/// The lantern's place in the models' order: the one model its own cube
/// leaves out, since its light is inside it.
pub const LANTERN_MODEL: usize = 1 + PropKind::ALL.len();

/// The props' OBJ files, kind by kind ([`PropKind::ALL`]), and the
/// player's, read from the chapter's built-in files; what the reader had
/// to say about them goes to `warnings`.
pub fn read_models(warnings: &mut Vec<String>) -> anyhow::Result<(Vec<obj::LoadedModel>, obj::LoadedModel)> {
    let read: obj::ReadFile = &scene::read;
    let mut load = |path: &str| -> anyhow::Result<obj::LoadedModel> {
        let loaded = obj::load(Path::new(path), read)?;
        warnings.extend(loaded.warnings.iter().cloned());
        Ok(loaded)
    };
    let props = PropKind::ALL.iter().map(|&kind| load(scene::prop_model(kind))).collect::<anyhow::Result<Vec<_>>>()?;
    let player = load(scene::PLAYER_MODEL)?;
    Ok((props, player))
}

/// The instances of the level (one), the props kind by kind (trees,
/// rocks, crates, islands, the sphere), the lantern, and a last one for
/// the player, with the draws that use them: (model, instances), the
/// model numbered as in [`LANTERN_MODEL`]'s order. Every draw casts the
/// sun's shadow; all but the lantern's cast the lantern's.
pub fn level_instances(level: &Level, game: &Game) -> (Vec<ModelInstance>, Vec<(usize, Range<u32>)>) {
    let mut instances = vec![ModelInstance::new(Mat4::IDENTITY, 1.0)];
    let mut draws = vec![(0, 0..1)];
    for (i, kind) in PropKind::ALL.into_iter().enumerate() {
        let start = instances.len() as u32;
        instances.extend(scene::prop_instances(level, kind));
        draws.push((1 + i, start..instances.len() as u32));
    }
    let start = instances.len() as u32;
    instances.push(scene::lantern_instance(level));
    draws.push((LANTERN_MODEL, start..start + 1));
    let start = instances.len() as u32;
    instances.push(scene::player_instance(game));
    draws.push((LANTERN_MODEL + 1, start..start + 1));
    (instances, draws)
}

/// The level's models, in the order the draws number them: the level,
/// one per prop kind ([`PropKind::ALL`]), the lantern, the player; their
/// materials; and every instance.
pub struct LevelModels {
    pub materials: Materials,
    level: GpuModel,
    props: Vec<GpuModel>,
    lantern: GpuModel,
    player: GpuModel,
    /// Every instance: the level's and the props', which never move, then
    /// the player's, written each frame.
    instances: wgpu::Buffer,
    /// Which model (an index into the models' order) draws which instances.
    draws: Vec<(usize, Range<u32>)>,
}

impl LevelModels {
    /// Uploads the level's models through `up`: the blocks and the lantern
    /// built by [`scene`], the `props` (kind by kind) and the `player` as
    /// read by [`read_models`].
    pub fn upload(
        gpu: &Gpu,
        up: &mut Uploader,
        level: &Level,
        props: &[obj::LoadedModel],
        player: &obj::LoadedModel,
    ) -> Self {
        let mut materials = Materials::new(up);
        let level_model = upload_model(up, &mut materials, &scene::level_model(level), "level");
        let props = props
            .iter()
            .zip(PropKind::ALL)
            .map(|(prop, kind)| upload_model(up, &mut materials, &prop.model, &format!("{kind:?}")))
            .collect();
        let lantern = upload_model(up, &mut materials, &scene::lantern_model(level), "lantern");
        let player = upload_model(up, &mut materials, &player.model, "player");
        let (instances, draws) = level_instances(level, &Game::new(level));
        let instances = wgpu::util::DeviceExt::create_buffer_init(
            &gpu.device,
            &wgpu::util::BufferInitDescriptor {
                label: Some("instances"),
                contents: bytemuck::cast_slice(&instances),
                usage: wgpu::BufferUsages::VERTEX | wgpu::BufferUsages::COPY_DST,
            },
        );
        Self { materials, level: level_model, props, lantern, player, instances, draws }
    }

    /// Moves the player's instance, the last one, to where `game` has it.
    pub fn place_player(&self, gpu: &Gpu, game: &Game) {
        let size = std::mem::size_of::<ModelInstance>() as u64;
        let offset = self.instances.size() - size;
        gpu.queue.write_buffer(&self.instances, offset, bytemuck::bytes_of(&scene::player_instance(game)));
    }

    /// The model numbered `i` in the draws' order.
    fn model(&self, i: usize) -> &GpuModel {
        match i {
            0 => &self.level,
            i if i == LANTERN_MODEL => &self.lantern,
            i if i == LANTERN_MODEL + 1 => &self.player,
            i => &self.props[i - 1],
        }
    }

    /// The draws of the models for which `keep` says yes.
    fn list(&self, keep: impl Fn(usize) -> bool) -> DrawList<'_> {
        DrawList {
            materials: &self.materials,
            instances: &self.instances,
            draws: self
                .draws
                .iter()
                .filter(|(i, _)| keep(*i))
                .map(|(i, instances)| Draw { model: self.model(*i), instances: instances.clone() })
                .collect(),
        }
    }

    /// Everything: what the sun's shadow map and the camera's pass draw.
    pub fn everything(&self) -> DrawList<'_> {
        self.list(|_| true)
    }

    /// Everything but the lantern, whose light is inside it: what the
    /// lantern's cube draws.
    pub fn lantern_casters(&self) -> DrawList<'_> {
        self.list(|i| i != LANTERN_MODEL)
    }
}
