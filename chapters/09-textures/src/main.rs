fn main() -> std::process::ExitCode {
    common::run::<textures::TexturesChapter>()
}
