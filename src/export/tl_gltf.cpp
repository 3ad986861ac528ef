// The glTF writer behind tl_export.h's C interface: tinygltf (Debian's
// libtinygltf-dev) builds and serialises the model, so that the JSON,
// base64 and GLB containers are its code, not ours. The only C++ here.
#include <cstring>
#include <sstream>
#include <string>
#include <vector>

#define TINYGLTF_NO_STB_IMAGE
#define TINYGLTF_NO_STB_IMAGE_WRITE
#define TINYGLTF_NO_EXTERNAL_IMAGE
#include <tiny_gltf.h>

extern "C" {
#include "export/tl_export.h"
}

namespace
{

// Appends `count` floats to the buffer as a view and an accessor of
// `components` floats each; returns the accessor's index.
int add_floats(tinygltf::Model &m, std::vector<unsigned char> &bytes, const float *data, int count,
               int components, bool bounds)
{
    tinygltf::BufferView view;
    view.buffer = 0;
    view.byteOffset = bytes.size();
    view.byteLength = sizeof(float) * (size_t)count * (size_t)components;
    const unsigned char *from = reinterpret_cast<const unsigned char *>(data);
    bytes.insert(bytes.end(), from, from + view.byteLength);
    m.bufferViews.push_back(view);

    tinygltf::Accessor a;
    a.bufferView = (int)m.bufferViews.size() - 1;
    a.componentType = TINYGLTF_COMPONENT_TYPE_FLOAT;
    a.count = (size_t)count;
    a.type = components == 1   ? TINYGLTF_TYPE_SCALAR
             : components == 3 ? TINYGLTF_TYPE_VEC3
                               : TINYGLTF_TYPE_VEC4;
    if (bounds) { // an animation's input needs its range
        double lo = data[0], hi = data[0];
        for (int i = 1; i < count; i++) {
            lo = data[i] < lo ? data[i] : lo;
            hi = data[i] > hi ? data[i] : hi;
        }
        a.minValues = {lo};
        a.maxValues = {hi};
    }
    m.accessors.push_back(a);
    return (int)m.accessors.size() - 1;
}

void add_channel(tinygltf::Animation &anim, int node, const char *path, int input, int output)
{
    tinygltf::AnimationSampler s;
    s.input = input;
    s.output = output;
    s.interpolation = "LINEAR";
    anim.samplers.push_back(s);
    tinygltf::AnimationChannel c;
    c.sampler = (int)anim.samplers.size() - 1;
    c.target_node = node;
    c.target_path = path;
    anim.channels.push_back(c);
}

} // namespace

extern "C" int tl_gltf_encode(const tl_gltf_node *nodes, int count, int frames, double fps,
                              int binary, unsigned char **out, size_t *size, char *why,
                              size_t why_size)
{
    *out = nullptr;
    *size = 0;
    try {
        tinygltf::Model m;
        m.asset.version = "2.0";
        m.asset.generator = "tideline";
        std::vector<unsigned char> bytes;
        std::vector<float> times((size_t)frames);
        for (int k = 0; k < frames; k++)
            times[(size_t)k] = (float)(k / fps);
        int input = add_floats(m, bytes, times.data(), frames, 1, true);

        tinygltf::Scene scene;
        scene.name = "tideline";
        tinygltf::Animation anim;
        anim.name = "tideline";
        for (int i = 0; i < count; i++) {
            const tl_gltf_node &n = nodes[i];
            tinygltf::Node node;
            node.name = n.name;
            node.translation = {n.translation[0], n.translation[1], n.translation[2]};
            node.rotation = {n.rotation[0], n.rotation[1], n.rotation[2], n.rotation[3]};
            if (n.kind == TL_GLTF_CAMERA) {
                tinygltf::Camera cam;
                cam.name = n.name;
                cam.type = "perspective";
                cam.perspective.yfov = n.yfov;
                cam.perspective.aspectRatio = n.aspect;
                cam.perspective.znear = 0.1;
                if (n.yfov_keys) { // the lens per frame (glTF animates no lens)
                    tinygltf::Value::Array keys;
                    for (int k = 0; k < frames; k++)
                        keys.push_back(tinygltf::Value((double)n.yfov_keys[k]));
                    tinygltf::Value::Object extras;
                    extras["tideline_yfov_per_frame"] = tinygltf::Value(keys);
                    cam.extras = tinygltf::Value(extras);
                }
                m.cameras.push_back(cam);
                node.camera = (int)m.cameras.size() - 1;
            } else if (n.kind == TL_GLTF_SUN) {
                tinygltf::Light light;
                light.name = n.name;
                light.type = "directional";
                light.color = {1.0, 1.0, 1.0};
                light.intensity = 1.0;
                m.lights.push_back(light);
                tinygltf::Value::Object ref;
                ref["light"] = tinygltf::Value((int)m.lights.size() - 1);
                node.extensions["KHR_lights_punctual"] = tinygltf::Value(ref);
            }
            m.nodes.push_back(node);
            scene.nodes.push_back((int)m.nodes.size() - 1);
            int t = add_floats(m, bytes, n.translation, frames, 3, false);
            int r = add_floats(m, bytes, n.rotation, frames, 4, false);
            add_channel(anim, (int)m.nodes.size() - 1, "translation", input, t);
            add_channel(anim, (int)m.nodes.size() - 1, "rotation", input, r);
        }
        tinygltf::Value::Object extras;
        extras["tideline_fps"] = tinygltf::Value(fps);
        scene.extras = tinygltf::Value(extras);
        m.scenes.push_back(scene);
        m.defaultScene = 0;
        m.animations.push_back(anim);
        tinygltf::Buffer buffer;
        buffer.data = bytes;
        m.buffers.push_back(buffer);

        tinygltf::TinyGLTF writer;
        std::ostringstream stream;
        if (!writer.WriteGltfSceneToStream(&m, stream, true, binary != 0)) {
            snprintf(why, why_size, "tinygltf could not write the scene");
            return -1;
        }
        const std::string text = stream.str();
        *out = static_cast<unsigned char *>(malloc(text.size()));
        if (!*out) {
            snprintf(why, why_size, "out of memory");
            return -1;
        }
        memcpy(*out, text.data(), text.size());
        *size = text.size();
        return 0;
    } catch (const std::exception &e) { // nothing C++ crosses into C
        snprintf(why, why_size, "%s", e.what());
        return -1;
    }
}
