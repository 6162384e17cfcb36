fn main() -> std::process::ExitCode {
    common::run::<shadows::ShadowsChapter>()
}
