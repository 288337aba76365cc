// The image module (host/image/image_module.h) gives its table only to a program built
// with the same table and Image: one from another build is refused, not called with the
// wrong layout. Broken variant seen to fail: the sizes not compared.
#include <dlfcn.h>
#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "image/image_module.h"

namespace pathcl::test_image_module {
namespace {

TEST(ImageModule, GivesItsTableOnlyToTheLayoutItWasBuiltWith)
{
    const std::string path = (std::filesystem::path(PATHCL_BINARY).parent_path() / "libpathcl_oiio.so").string();
    void* handle = ::dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
    ASSERT_NE(handle, nullptr) << ::dlerror();
    auto entry = reinterpret_cast<decltype(&pathcl_image_module)>(::dlsym(handle, "pathcl_image_module"));
    ASSERT_NE(entry, nullptr);
    EXPECT_NE(entry(kImageModuleAbi, sizeof(Image), sizeof(ImageModule)), nullptr);
    EXPECT_EQ(entry(kImageModuleAbi + 1, sizeof(Image), sizeof(ImageModule)), nullptr);
    EXPECT_EQ(entry(kImageModuleAbi, sizeof(Image) + 8, sizeof(ImageModule)), nullptr);
    EXPECT_EQ(entry(kImageModuleAbi, sizeof(Image), sizeof(ImageModule) + 8), nullptr);
    // The loader's table is that one.
    EXPECT_EQ(&image_module(), entry(kImageModuleAbi, sizeof(Image), sizeof(ImageModule)));
}

} // namespace
} // namespace pathcl::test_image_module
