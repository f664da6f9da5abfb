// The JSON files of ../shared/scenes/json whose camera, lights, shaders and shapes equal an XML file
// of ../shared/scenes/upstream (SOURCES.md there, checked field by field by the loader's JsonTwins
// test). Two differ in the background only: mirrorScene01.json drops mirrorTest2.xml's bgColor
// "1 0 0", and sd20190224_spheres_1K.json has _bgColor "0.0 0.8 1.0"; image tests render those with
// the same background override on both sides.
#pragma once

namespace vkrt::test {

struct JsonTwin {
    const char* json;     // stem, in ../shared/scenes/json
    const char* xml;      // stem, in ../shared/scenes/upstream
    bool sameBackground;
};

inline constexpr JsonTwin kJsonTwins[] = {{"oneSphere", "oneSphere", true},
                                          {"oneTriangle", "oneTriangle", true},
                                          {"threeTriangles", "threeTriangles", true},
                                          {"sd20180202_threeTriangles", "threeTriangles", true},
                                          {"PhongExp", "PhongExp", true},
                                          {"lambertianChalkSpheres", "lambertianChalkSpheres", true},
                                          {"simpleSphereScene", "simpleSphereScene", true},
                                          {"areaLight", "areaLight", true},
                                          {"glazeTest", "glazeTest", true},
                                          {"threeEggs", "threeEggs", true},
                                          {"sd20190425_threeEggs", "threeEggs", true},
                                          {"metallicDragons", "metallicDragons", true},
                                          {"sd20190425_metallicDragons", "metallicDragons", true},
                                          {"oneBox", "sd2019_oneBox", true},
                                          {"sd20190227_mirrorScene00", "mirrorTest", true},
                                          {"mirrorScene01", "mirrorTest2", false},
                                          {"sd20190224_spheres_1K", "spheres_1K", false}};

}  // namespace vkrt::test
