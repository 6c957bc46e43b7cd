# Every dependency is a Debian 12 package (scripts/debian-packages.txt); nothing is downloaded.
find_package(Eigen3 3.4 REQUIRED NO_MODULE)
find_package(CGAL 5.5 REQUIRED)
find_package(TBB REQUIRED)
find_package(OpenMesh CONFIG REQUIRED)
find_package(nanoflann REQUIRED)
find_path(LBFGSPP_INCLUDE_DIR LBFGS.h PATH_SUFFIXES LBFGSpp REQUIRED)
get_filename_component(LBFGSPP_INCLUDE_DIR ${LBFGSPP_INCLUDE_DIR} DIRECTORY)
find_path(TETGEN_INCLUDE_DIR tetgen.h REQUIRED)
find_library(TETGEN_LIBRARY NAMES tet REQUIRED)

# Debian's VTK config needs MPI's C component found first. Its Qt modules link Qt5: never use them.
find_package(MPI COMPONENTS C)
set(STRATAMESH_VTK_IO_COMPONENTS CommonCore CommonDataModel CommonExecutionModel IOLegacy IOXML
    FiltersVerdict FiltersCore)
set(STRATAMESH_VTK_VIEW_COMPONENTS RenderingCore RenderingOpenGL2 RenderingFreeType
    RenderingAnnotation InteractionStyle InteractionWidgets FiltersSources FiltersGeometry
    FiltersExtraction FiltersModeling)
if(STRATAMESH_BUILD_GUI)
  find_package(VTK 9.1 REQUIRED COMPONENTS ${STRATAMESH_VTK_IO_COMPONENTS} ${STRATAMESH_VTK_VIEW_COMPONENTS})
else()
  find_package(VTK 9.1 REQUIRED COMPONENTS ${STRATAMESH_VTK_IO_COMPONENTS})
endif()

set(STRATAMESH_QT_COMPONENTS Core Concurrent Test)
if(STRATAMESH_BUILD_GUI)
  list(APPEND STRATAMESH_QT_COMPONENTS Gui Widgets OpenGL OpenGLWidgets Charts LinguistTools)
endif()
find_package(Qt6 6.4 REQUIRED COMPONENTS ${STRATAMESH_QT_COMPONENTS})
qt_standard_project_setup()
set(CMAKE_AUTOMOC ON)

add_library(stratamesh_lbfgspp INTERFACE)
target_include_directories(stratamesh_lbfgspp SYSTEM INTERFACE ${LBFGSPP_INCLUDE_DIR})
add_library(stratamesh_tetgen INTERFACE)
target_include_directories(stratamesh_tetgen SYSTEM INTERFACE ${TETGEN_INCLUDE_DIR})
target_compile_definitions(stratamesh_tetgen INTERFACE TETLIBRARY)
target_link_libraries(stratamesh_tetgen INTERFACE ${TETGEN_LIBRARY})
