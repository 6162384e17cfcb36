fn main() -> std::process::ExitCode {
    common::run::<skybox::SkyboxChapter>()
}
