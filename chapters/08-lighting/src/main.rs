fn main() -> std::process::ExitCode {
    common::run::<lighting::LightingChapter>()
}
