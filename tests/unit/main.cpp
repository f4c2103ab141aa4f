#define BOOST_TEST_MODULE tmcert_unit
#include <boost/test/unit_test.hpp>
