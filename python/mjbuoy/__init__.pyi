from ._mjbuoy import PARTS as PARTS
from ._mjbuoy import Batch as Batch
from ._mjbuoy import Error as Error
from ._mjbuoy import Sim as Sim
from ._mjbuoy import __version__ as __version__
