fn main() -> std::process::ExitCode {
    common::run::<camera::CameraChapter>()
}
