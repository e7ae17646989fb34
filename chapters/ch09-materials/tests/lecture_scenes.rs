//! On a scene of the lecture's materials this crate is chapter 08, bit for bit: its BSDF hands
//! every lecture material to chapter 08's, which draws the same numbers in the same order, so
//! the two renderers make the same image of every scene chapter 08 checks against Mitsuba 3
//! (and a difference in one pixel is a material that no longer delegates).

use ch08_path_tracing::lab::agreement::AGREEMENT as LECTURE;

#[test]
fn every_scene_of_chapter_08_renders_as_chapter_08_renders_it() {
    assert!(!LECTURE.scenes.is_empty());
    for scene in LECTURE.scenes {
        let file = LECTURE.scenes_dir().join(format!("{}.xml", scene.name));
        let lecture = (LECTURE.render)(&file).unwrap();
        let ours = ch09_materials::lab::agreement::render_scene_file(&file).unwrap();
        assert_eq!(
            (ours.width, ours.height),
            (lecture.width, lecture.height),
            "{}",
            scene.name
        );
        let differing = ours
            .pixels
            .iter()
            .zip(&lecture.pixels)
            .filter(|(a, b)| a.to_array().map(f32::to_bits) != b.to_array().map(f32::to_bits))
            .count();
        assert_eq!(
            differing, 0,
            "{}: {differing} pixels differ from chapter 08's image",
            scene.name
        );
    }
}
