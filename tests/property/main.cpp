// Boost.Test main of the property tests (rapidcheck properties registered as
// Boost test cases).  Replay a failure with RC_PARAMS="seed=N".
#define BOOST_TEST_MODULE tmcert_property
#include <boost/test/unit_test.hpp>
