// placeholder until the module lands
namespace grape {}
