// OpenColorIO behind tl_ocio.h's C interface: configs, the working space's
// matrix and the display transform's table. Nothing C++ crosses into C:
// every OpenColorIO exception becomes a tl_error.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include <OpenColorIO/OpenColorIO.h>

extern "C" {
#include "ocio/tl_ocio.h"
}

namespace OCIO = OCIO_NAMESPACE;

// The built-in config's text (src/ocio/tideline.ocio), generated at build.
#include "tl_ocio_config.h"

namespace
{

const char *const kRadiance = "Linear Rec.709";

OCIO::ConstConfigRcPtr builtin_config()
{
    std::istringstream text(tl_ocio_builtin_config);
    return OCIO::Config::CreateFromStream(text);
}

} // namespace

struct tl_ocio_display {
    OCIO::ConstCPUProcessorRcPtr cpu;
    std::string describe;
};

extern "C" int tl_ocio_working_matrix(tl_working_space space, double m[9], tl_error *err)
{
    try {
        OCIO::ConstConfigRcPtr config = builtin_config();
        const char *to = space == TL_WORKING_ACESCG ? "ACEScg" : kRadiance;
        OCIO::ConstCPUProcessorRcPtr cpu =
            config->getProcessor(kRadiance, to)->getOptimizedCPUProcessor(OCIO::OPTIMIZATION_NONE);
        // A linear conversion: its columns are the images of the unit colours.
        for (int c = 0; c < 3; c++) {
            float rgb[3] = {0.0f, 0.0f, 0.0f};
            rgb[c] = 1.0f;
            cpu->applyRGB(rgb);
            for (int r = 0; r < 3; r++)
                m[r * 3 + c] = rgb[r];
        }
        return TL_OK;
    } catch (const std::exception &e) { // OpenColorIO's own, or out of memory
        return tl_error_set(err, TL_ERR_RUNTIME, "OpenColorIO: %s", e.what());
    }
}

// The names a config offers, for an error message: "a, b, c".
static std::string listing(int count, const char *(*name)(const OCIO::Config &, int),
                           const OCIO::Config &config)
{
    std::string out;
    for (int i = 0; i < count; i++)
        out += (i ? ", " : "") + std::string(name(config, i));
    return out;
}

extern "C" int tl_ocio_display_open(const char *config_path, const char *display, const char *view,
                                    tl_ocio_display **out, tl_error *err)
{
    *out = nullptr;
    const char *env = getenv("OCIO");
    std::string where = config_path ? config_path : (env && env[0] ? env : "built-in");
    try {
        OCIO::ConstConfigRcPtr config;
        if (config_path)
            config = OCIO::Config::CreateFromFile(config_path);
        else if (env && env[0])
            config = OCIO::Config::CreateFromEnv();
        else
            config = builtin_config();
        config->validate();
        const char *d = display ? display : config->getDefaultDisplay();
        bool known = false;
        for (int i = 0; i < config->getNumDisplays(); i++)
            known |= strcmp(config->getDisplay(i), d) == 0;
        if (!known)
            return tl_error_set(
                err, TL_ERR_USAGE, "%s: no display '%s' (displays: %s)", where.c_str(), d,
                listing(
                    config->getNumDisplays(),
                    [](const OCIO::Config &c, int i) { return c.getDisplay(i); }, *config)
                    .c_str());
        const char *v = view ? view : config->getDefaultView(d);
        known = false;
        std::string views;
        for (int i = 0; i < config->getNumViews(d); i++) {
            known |= strcmp(config->getView(d, i), v) == 0;
            views += (i ? ", " : "") + std::string(config->getView(d, i));
        }
        if (!known)
            return tl_error_set(err, TL_ERR_USAGE, "%s: display '%s' has no view '%s' (views: %s)",
                                where.c_str(), d, v, views.c_str());
        // The radiance into the config's own scene-linear space by way of
        // ACES2065-1 (both configs' aces_interchange role), then its
        // display and view.
        OCIO::ConstConfigRcPtr ours = builtin_config();
        if (!config->hasRole("aces_interchange"))
            return tl_error_set(err, TL_ERR_USAGE,
                                "OpenColorIO config %s%s has no aces_interchange role (an "
                                "OpenColorIO 1 config?): tideline brings its linear Rec.709 "
                                "into a config through ACES2065-1; give --ocio a config with "
                                "the role%s",
                                where.c_str(), config_path ? "" : " ($OCIO)",
                                config_path ? "" : ", or unset $OCIO for the ACES fit");
        OCIO::ConstProcessorRcPtr into =
            OCIO::Config::GetProcessorFromConfigs(ours, kRadiance, config, OCIO::ROLE_SCENE_LINEAR);
        OCIO::DisplayViewTransformRcPtr dv = OCIO::DisplayViewTransform::Create();
        dv->setSrc(OCIO::ROLE_SCENE_LINEAR);
        dv->setDisplay(d);
        dv->setView(v);
        OCIO::GroupTransformRcPtr group = OCIO::GroupTransform::Create();
        group->appendTransform(into->createGroupTransform());
        group->appendTransform(dv);
        OCIO::ConstProcessorRcPtr all = config->getProcessor(group);
        std::unique_ptr<tl_ocio_display> cd(new tl_ocio_display);
        cd->cpu = all->getDefaultCPUProcessor();
        cd->describe = where + ": " + d + " / " + v;
        *out = cd.release();
        return TL_OK;
    } catch (const OCIO::Exception &e) {
        return tl_error_set(err, config_path || (env && env[0]) ? TL_ERR_USAGE : TL_ERR_RUNTIME,
                            "OpenColorIO config %s: %s", where.c_str(), e.what());
    } catch (const std::exception &e) {
        return tl_error_set(err, TL_ERR_RUNTIME, "OpenColorIO config %s: %s", where.c_str(),
                            e.what());
    }
}

extern "C" void tl_ocio_display_close(tl_ocio_display *d)
{
    delete d;
}

extern "C" const char *tl_ocio_display_describe(const tl_ocio_display *d)
{
    return d->describe.c_str();
}

extern "C" void tl_ocio_display_apply(const tl_ocio_display *d, const float in[3], float out[3])
{
    float rgb[3] = {in[0], in[1], in[2]};
    d->cpu->applyRGB(rgb);
    for (int c = 0; c < 3; c++)
        out[c] = std::isfinite(rgb[c]) ? rgb[c] : 0.0f;
}

extern "C" int tl_ocio_display_bake(const tl_ocio_display *d, int n, float *rgb, tl_error *err)
{
    if (n < 2)
        return tl_error_set(err, TL_ERR_RUNTIME, "a display table needs 2 entries an axis");
    std::vector<float> axis((size_t)n);
    for (int i = 0; i < n; i++)
        axis[(size_t)i] = (float)exp2(TL_COLOR_SHAPER_LO +
                                      (TL_COLOR_SHAPER_HI - TL_COLOR_SHAPER_LO) * i / (n - 1));
    try {
        size_t k = 0;
        for (int b = 0; b < n; b++)
            for (int g = 0; g < n; g++)
                for (int r = 0; r < n; r++, k += 3) {
                    const float in[3] = {axis[(size_t)r], axis[(size_t)g], axis[(size_t)b]};
                    tl_ocio_display_apply(d, in, rgb + k);
                }
        return TL_OK;
    } catch (const std::exception &e) { // OpenColorIO's own, or out of memory
        return tl_error_set(err, TL_ERR_RUNTIME, "OpenColorIO: %s", e.what());
    }
}
