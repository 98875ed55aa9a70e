from ._BoolStamped import *
from ._Float64Stamped import *
from ._Int32Stamped import *
from ._Int8Stamped import *
from ._StringStamped import *
