fn main() -> std::process::ExitCode {
    common::run::<fog::FogChapter>()
}
