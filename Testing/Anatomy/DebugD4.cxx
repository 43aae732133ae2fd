#include <gtest/gtest.h>
#include "ImageGeometry.h"
#include "IO/ReadCtImage.h"
#include "PipelineSupport.h"
#include <random>
namespace sgp {
TEST(Debug, D4) {
  auto mask = ReadLabelMap(std::string(SGP_SHARED_DIR) + "/data/avt/avt_dongyang_D3.seg.nrrd");
  auto sk = ThinLabelMap(*mask);
  auto g = BuildSkeletonGraph(sk, *mask);
  Point3 seed = IndexToLps(*mask, {{246,306,42}});
  for (int n = 0; n < (int)g.nodes.size(); ++n) {
    if (g.Degree(n) < 3 || ((g.nodes[n].position - seed).norm() > 60 && std::abs(g.nodes[n].position.z() - 540) > 25)) continue;
    std::cout << "node " << n << " at " << g.nodes[n].position.transpose() << " r " << g.nodes[n].radiusMm << "\n";
    for (int e : g.nodes[n].edges) {
      auto pts = PointsFrom(g, e, n);
      Point3 far = pts.back(); double s=0; for (size_t i=1;i<pts.size();++i){ s+=(pts[i]-pts[i-1]).norm(); if (s>=20){far=pts[i];break;} }
      std::cout << "   edge " << e << " len " << g.edges[e].lengthMm << " dir " << (far - g.nodes[n].position).normalized().transpose() << " r0 " << RadiiFrom(g,e,n)[std::min<size_t>(5,pts.size()-1)] << "\n";
    }
  }
}
}
